"""Library functions lifted out of the paper modules (issue 19, item 3).

Each is checked against an independent recomputation from its equation, and against the
paper module's own helper where one exists (read-only), so that the paper module can call
the library instead.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from navcore.estimation.federated import federated_improvement_db, minkowski_trace_bound
from navcore.location.clock_tracking import alpha_parameter, psi, tracking_position_errors
from navcore.papers import atc10_tracking, wf
from navcore.units import FT, C


def _table_4_3_oracle(inputs: dict[str, float], sigma0: float, sigma: float, c: float) -> tuple[float, ...]:
    """ATC-10 Eqs. 4.5.27, 4.5.32-4.5.35 written out."""
    a = 8.0 / 27.0 * sigma0**2 * inputs["beta"] / sigma**2
    r = math.sqrt(1.0 + a)
    p = 1.5 * a ** (1 / 3) * (np.cbrt(1.0 + r) + np.cbrt(1.0 - r))
    b = inputs["beta"]
    sd0 = c * sigma * math.sqrt(inputs["trace_all"] + inputs["s_all"] / b)
    sdn = c * sigma * math.sqrt(inputs["trace_all"] + p / b * inputs["s_all"])
    sdn1 = c * sigma * math.sqrt(inputs["trace_123"] + (p + 27 / 4 * a / p) / b * inputs["s_123"])
    return a, p, sd0, sdn, sdn1


@pytest.mark.parametrize("example", ["I", "II"])
@pytest.mark.parametrize("sigma0", [1.0, 5.0, 20.0])
def test_tracking_position_errors_matches_paper_row_and_oracle(example, sigma0):
    inputs = atc10_tracking.printed_table_4_2(example)
    row = tracking_position_errors(
        inputs["trace_all"],
        inputs["s_all"],
        inputs["trace_123"],
        inputs["s_123"],
        inputs["beta"],
        sigma0,
        atc10_tracking.IN.sigma_ns,
        c=atc10_tracking.IN.c_ft_per_ns,
    )
    assert tuple(row) == pytest.approx(atc10_tracking.table_4_3_row(inputs, sigma0), rel=1e-12)
    oracle = _table_4_3_oracle(inputs, sigma0, atc10_tracking.IN.sigma_ns, atc10_tracking.IN.c_ft_per_ns)
    assert tuple(row) == pytest.approx(oracle, rel=1e-10)
    assert row.alpha == alpha_parameter(sigma0, atc10_tracking.IN.sigma_ns, inputs["beta"])
    assert row.psi == pytest.approx(float(psi(row.alpha)))


def test_tracking_position_errors_convention_is_a_parameter():
    """Physical c in SI: sigma in seconds gives metres, the ft/ns convention gives ns numbers."""
    inputs = atc10_tracking.printed_table_4_2("I")
    args = (inputs["trace_all"], inputs["s_all"], inputs["trace_123"], inputs["s_123"], inputs["beta"])
    ns = tracking_position_errors(*args, 5.0, 50.0, c=1.0)
    si = tracking_position_errors(*args, 5e-9, 50e-9, c=C)
    assert si.sd_least_squares / FT == pytest.approx(ns.sd_least_squares * C * 1e-9 / FT, rel=1e-12)
    assert si.sd_least_squares / FT / ns.sd_least_squares == pytest.approx(0.98357, abs=1e-5)
    with pytest.raises(TypeError):
        tracking_position_errors(*args, 5.0, 50.0)  # type: ignore[call-arg]  # c has no default
    with pytest.raises(ValueError, match="sigma0"):
        tracking_position_errors(*args, -1.0, 50.0, c=1.0)


@pytest.mark.parametrize(("sigma_a", "sigma_t", "n_sat"), [(3e-4, 0.0, 0), (3e-4, 0.01, 3), (1e-3, 0.02, 1)])
def test_federated_improvement_db_matches_wf(sigma_a, sigma_t, n_sat):
    covs = wf.local_covariances(sigma_a, sigma_t, n_sat)
    reference = math.hypot(wf.IN.sigma_n, sigma_t)
    lib = federated_improvement_db(covs, reference)
    assert lib == pytest.approx(wf.improvement_db(sigma_a, sigma_t, n_sat), abs=1e-12)
    oracle = 20 * math.log10(math.sqrt(minkowski_trace_bound(covs) / 3) / reference)  # WF Eq. (23)
    assert lib == pytest.approx(oracle, abs=1e-12)


def test_federated_improvement_db_rejects_bad_reference():
    with pytest.raises(ValueError, match="reference_sigma"):
        federated_improvement_db([np.eye(3)], 0.0)
