"""ATC-10 Secs. 1-2: design points, ceilings and the printed-(2.8.1) negative control."""

from __future__ import annotations

import math

import numpy as np
import pytest

from navcore.detection import jamming as jm
from navcore.papers import atc10_jamming as paper


@pytest.mark.parametrize(
    ("k", "p_dl", "p_d"),
    [(1, 0.88, 0.968547), (10, 0.88, 0.661136), (100, 0.999, 0.508283), (1000, 0.98, 0.249970)],
)
def test_design_points(k: int, p_dl: float, p_d: float) -> None:
    """Oracle: hand inversion p_d = [1 - (1 - P_DL)^(1/K)]^(1/4) to six digits."""
    assert paper.design_p_d(p_dl, k) == pytest.approx((1 - (1 - p_dl) ** (1 / k)) ** 0.25, rel=1e-12)
    assert paper.design_p_d(p_dl, k) == pytest.approx(p_d, abs=1e-6)


def test_printed_281_argument_misses_table_21() -> None:
    """Oracle: the printed (2.8.1) reads p_f = Q(d/sqrt(2) - Phi^-1(p_d)), i.e. the bound at 2x;
    solving the bound with that p_f (an independent root search) lands 3.01 dB below the print."""
    for k, p_dl, text, rel in paper.TABLE_2_1:
        if rel != "=" or k == 1000:
            continue
        p_d = paper.design_p_d(p_dl, k)

        def f(x_db: float, p_d: float = p_d, k: int = k) -> float:
            x_eff = 2 * 10 ** (x_db / 10)
            return float(jm.log_ambiguous_detection_bound(x_eff, p_d, k)) - math.log(0.01)

        from scipy import optimize

        x_printed = optimize.brentq(f, -40, 60)
        erp_printed = x_printed + 50.0
        assert abs(erp_printed - float(text)) > 2.5
        assert paper.required_erp_dbw("ambiguous", p_dl, k) - erp_printed == pytest.approx(
            10 * np.log10(2), abs=1e-6
        )


def test_ceilings() -> None:
    """Oracle: closed forms at J -> inf: 0.05 P_DL N_T for K <= 100 and the K = 1000 values."""
    for k, p_dl in ((1, 0.88), (10, 0.999), (100, 0.999)):
        c = math.exp(jm.log_ambiguous_detection_ceiling(paper.design_p_d(p_dl, k), k))
        assert c == pytest.approx(0.05 * p_dl, rel=3e-3)
    c = math.exp(jm.log_ambiguous_detection_ceiling(paper.design_p_d(0.98, 1000), 1000))
    assert c == pytest.approx(0.002128, rel=1e-3)
    assert 0.9954 < paper.k1000_critical_p_dl() < 0.9955


def test_table11_k100_would_need_pdl_098() -> None:
    """Oracle: plain-probability grid search (direct_adl_erp_dbw): P_DL = 0.98 gives 53 dBW at K = 100."""
    assert paper.direct_adl_erp_dbw(0.98, 100) == pytest.approx(53.0, abs=0.1)
    assert paper.required_erp_dbw("ambiguous", 0.98, 100) == pytest.approx(
        paper.direct_adl_erp_dbw(0.98, 100), abs=1e-3
    )
