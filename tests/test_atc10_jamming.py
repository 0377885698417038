"""ATC-10 Secs. 1-2: design points, ceilings and the printed-(2.8.1) negative control."""

from __future__ import annotations

import itertools
import math

import mpmath
import numpy as np
import pytest
from scipy import optimize, stats

from navcore.detection import jamming as jm
from navcore.papers import atc10_jamming as paper
from navcore.papers import atc10_jamming_appendices as appendices
from navcore.papers import atc10_system_tables as tables
from navcore.papers import atc10_tracking_lists as lists


@pytest.mark.parametrize(("k", "p_dl"), [(1, 0.88), (10, 0.88), (100, 0.999), (1000, 0.98)])
def test_design_points(k: int, p_dl: float) -> None:
    """Oracle: the forward definition, P(at least one of K lists non-empty) = P_DL, with
    scipy.stats.binom and a list non-empty with probability p_d^4 (four filters)."""
    p_d = paper.design_p_d(p_dl, k)
    assert stats.binom.sf(0, k, p_d**4) == pytest.approx(p_dl, rel=1e-12)


def test_printed_281_argument_misses_table_21() -> None:
    """Oracle: the printed (2.8.1) reads p_f = Q(d/sqrt(2) - Phi^-1(p_d)), i.e. the bound at 2x;
    solving the bound with that p_f (an independent root search) lands 3.01 dB below the print."""
    g = paper.geometry()
    for k, p_dl, text, rel in paper.TABLE_2_1:
        if rel != "=" or k == 1000:
            continue
        p_d = paper.design_p_d(p_dl, k)

        def f(x_db: float, p_d: float = p_d, k: int = k) -> float:
            x_eff = 2 * 10 ** (x_db / 10)
            return float(jm.log_ambiguous_detection_bound(x_eff, p_d, k, 0.0, g)) - math.log(0.01)

        x_printed = optimize.brentq(f, -40, 60)
        erp_printed = x_printed + 50.0
        assert abs(erp_printed - float(text)) > 2.5
        assert paper.required_erp_dbw("ambiguous", p_dl, k) - erp_printed == pytest.approx(
            10 * np.log10(2), abs=1e-6
        )


def _mp_log_ceiling(p_dl: float, k: int) -> mpmath.mpf:
    """ln N_ADL/N_T at J -> inf (p_f = p_d), t = 0, at 50 digits: ln(N/(2 N_T) P_DL) +
    (K - 1) ln G(p_d) + ln F(p_d), with p_d = [1 - (1 - P_DL)^(1/K)]^(1/4) and the paper's counts."""
    g = paper.geometry()
    with mpmath.workdps(50):
        p_dl = mpmath.mpf(p_dl)
        p_d = (1 - (1 - p_dl) ** (mpmath.mpf(1) / k)) ** mpmath.mpf(0.25)

        def one_minus_power(n: float) -> mpmath.mpf:
            return mpmath.log(-mpmath.expm1(n * mpmath.log1p(-p_d)))

        log_f = one_minus_power(g.samples_per_period) + 3 * one_minus_power(g.samples_per_delay_window)
        log_g = one_minus_power(g.samples_per_period) + 3 * one_minus_power(g.samples_per_track_window)
        return mpmath.log(mpmath.mpf(g.airborne_fraction) / 2 * p_dl) + (k - 1) * log_g + log_f


def test_ceilings() -> None:
    """Oracle: the ceilings at J -> inf from 50-digit mpmath (_mp_log_ceiling): about
    0.05 P_DL N_T for K <= 100; at K = 1000 the P_DL where the ceiling reaches 0.01 N_T by a
    root search (brentq) on the mpmath ceiling."""
    g = paper.geometry()
    for k, p_dl in ((1, 0.88), (10, 0.999), (100, 0.999), (1000, 0.98)):
        c = jm.log_ambiguous_detection_ceiling(paper.design_p_d(p_dl, k), k, 0.0, g)
        assert c == pytest.approx(float(_mp_log_ceiling(p_dl, k)), rel=1e-10)
        if k <= 100:
            assert math.exp(c) == pytest.approx(0.05 * p_dl, rel=3e-3)
    critical = optimize.brentq(
        lambda p: float(_mp_log_ceiling(p, 1000)) - math.log(0.01), 0.98, 0.9999, xtol=1e-14, rtol=1e-14
    )
    assert lists.k1000_critical_p_dl() == pytest.approx(float(critical), rel=1e-9)


def test_table11_k100_would_need_pdl_098() -> None:
    """Oracle: plain-probability grid search (direct_adl_erp_dbw): P_DL = 0.98 gives 53 dBW at K = 100."""
    assert tables.direct_adl_erp_dbw(0.98, 100) == pytest.approx(53.0, abs=0.1)
    assert paper.required_erp_dbw("ambiguous", 0.98, 100) == pytest.approx(
        tables.direct_adl_erp_dbw(0.98, 100), abs=1e-3
    )


def test_pulse_energy_input_matches_printed_power_and_duration() -> None:
    """Oracle: hand arithmetic, 30 dBW = 1000 W, 1000 W x 10 us = 10 mJ, and 10 mJ x 10 MHz = 50 dBW.

    The thresholds read the one published pulse input IN.pulse_energy_j (the printed 10 mJ); it must
    equal the printed P0 tau, and changing it must move every ERP by the same dB.
    """
    from navcore.claims.inputs import overriding

    assert paper.IN.pulse_power_dbw == 30.0 and paper.IN.pulse_duration_s == 10e-6
    assert paper.geometry().pulse_energy_j == pytest.approx(1000.0 * 10e-6, rel=1e-15)
    assert paper.geometry().energy_bandwidth_dbw == pytest.approx(50.0, abs=1e-12)
    base = paper.required_erp_dbw("ambiguous", 0.999, 10)
    with overriding({"ATC10.jamming.pulse_energy_j": 20e-3}):
        moved = paper.required_erp_dbw("ambiguous", 0.999, 10)
    assert moved - base == pytest.approx(10 * math.log10(2), abs=1e-9)


def test_erp_by_transmission_length_against_direct_oracle() -> None:
    """Oracle: the plain-probability grid search (direct_adl_erp_dbw) at every K of Table 1.1.

    Sec. 1.1: the ERP rises with K; at the caption's P_D = 0.88 the K = 1000 system has no finite
    threshold, at P_DL = 0.999 it has one.
    """
    for p_dl in (0.88, 0.999):
        model = tables.erp_by_transmission_length(p_dl)
        direct = [tables.direct_adl_erp_dbw(p_dl, k) for k in paper.TABLE_1_1_KS]
        for m, d in zip(model, direct, strict=True):
            assert (math.isinf(m) and math.isinf(d)) or m == pytest.approx(d, abs=0.01)
        assert all(a < b for a, b in itertools.pairwise(direct))
    assert math.isinf(tables.erp_by_transmission_length(0.88)[-1])
    assert math.isfinite(tables.erp_by_transmission_length(0.999)[-1])


def test_threshold_helpers_for_the_errata() -> None:
    """Oracle: re-evaluating the bounds at the returned thresholds (an independent forward check)."""
    # without the P_DL factor: 1/2 N G^(K-1) F = 0.01 N_T at the returned ERP
    full = paper.geometry()
    for p_dl, k in ((0.88, 1), (0.999, 100)):
        x = 10 ** ((paper.adl_erp_dbw_without_pdl_factor(p_dl, k) - 50.0) / 10)
        p_d = paper.design_p_d(p_dl, k)
        log_n = float(jm.log_ambiguous_detection_bound(x, p_d, k, 0.0, full)) - float(
            jm.log_detection_lower_bound(p_d, k)
        )
        assert math.exp(log_n) == pytest.approx(0.01, rel=1e-8)
        assert paper.adl_erp_dbw_without_pdl_factor(p_dl, k) < paper.required_erp_dbw("ambiguous", p_dl, k)
    # half the samples: every count of (B.6) and (C.14) halves, the ERP scale does not
    half, full = paper.half_samples_geometry(), paper.geometry()
    assert half.samples_per_period == full.samples_per_period / 2
    assert half.samples_per_delay_window == pytest.approx(full.samples_per_delay_window / 2, rel=1e-15)
    assert half.samples_per_track_window == pytest.approx(full.samples_per_track_window / 2, rel=1e-15)
    x = 10 ** ((paper.adl_erp_dbw_half_samples(0.88, 100) - 50.0) / 10)
    n = math.exp(float(jm.log_ambiguous_detection_bound(x, paper.design_p_d(0.88, 100), 100, 0.0, half)))
    assert n == pytest.approx(0.01, rel=1e-8)
    # the p_f at the K = 1000, P_DL = 0.999 threshold: the root in p_f of 1/2 (N/N_T) P_DL G^999 F
    # = 0.01, in plain floating point (log1p), found by brentq without the dB search
    k, p_dl = 1000, 0.999

    def log_adl(p_f: float) -> float:
        def lom(n: float) -> float:
            return math.log(-math.expm1(n * math.log1p(-p_f)))

        log_f = lom(full.samples_per_period) + 3 * lom(full.samples_per_delay_window)
        log_g = lom(full.samples_per_period) + 3 * lom(full.samples_per_track_window)
        return math.log(full.airborne_fraction / 2 * p_dl) + (k - 1) * log_g + log_f - math.log(0.01)

    p_f = optimize.brentq(log_adl, 0.01, paper.design_p_d(p_dl, k), xtol=1e-15)
    assert math.exp(lists.threshold_log_pf(p_dl, k)) == pytest.approx(p_f, rel=1e-8)


def test_errata_numbers_match_the_model() -> None:
    """Oracle: the model itself. The errata are declared before anything is computed, so their
    numbers are typed; this test recomputes each and checks the text."""
    from navcore.claims.inputs import recording

    errata = [*paper.ERRATA, *appendices.ERRATA, *tables.ERRATA]
    text = {e.id: e.finding + " " + e.evidence for e in errata}
    g = paper.geometry()
    assert f"{g.max_speed_m_s * g.repetition_s / 299792458.0 * 1e6:.3f} µs" in text[appendices.E_C2]
    with recording():
        scaled = tables.table11_k1_beamwidth_scaled_deg()
    assert f"About {scaled:.1f} degrees" in text[tables.E_BEAM]
    assert (
        f"$P_{{DL}} = 0.98$ gives {paper.required_erp_dbw('ambiguous', 0.98, 100):.1f}"
        in text[tables.E_TAB11]
    )


def test_pencil_beam_constant_is_solved_from_sec_27() -> None:
    """Oracle: hand arithmetic, C = 20^2 x 10^((33 - 10 log10 30)/10); the declared fitted value is that
    solution (to three figures), and the K = 1 claim does not depend on it."""
    from navcore.claims.inputs import overriding, recording

    c = 20.0**2 * 10 ** ((33.0 - 10 * math.log10(30.0)) / 10)
    inp = paper.IN.input("pencil_beam_constant_deg2")
    assert inp.provenance == "fitted" and inp.fitted_to == ("ATC10-sec2.7-20deg",)
    assert inp.value == pytest.approx(c, abs=5.0)
    with recording() as reads:
        base = tables.table11_k1_beamwidth_scaled_deg()
    assert "ATC10.jamming.pencil_beam_constant_deg2" not in reads
    with overriding({"ATC10.jamming.pencil_beam_constant_deg2": 41253.0}), recording():
        assert tables.table11_k1_beamwidth_scaled_deg() == base
    # two dishes of the two gains: 20 deg x D_2.7 / D_K1, whatever the frequency and efficiency
    assert base == pytest.approx(
        20.0 * math.sqrt(10 ** ((33.0 - 10 * math.log10(30.0) - 18.0) / 10)), rel=1e-12
    )
    assert base == pytest.approx(tables._oracle_k1_beamwidth_scaled_deg(), rel=1e-12)
