"""Library functions lifted out of the paper modules (issue 19, item 3).

Each is checked against an independent oracle (a different algorithm or a closed form), and
against the paper module's own helper where one exists, so that the paper module can call the
library instead.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from navcore.estimation.federated import federated_improvement_db
from navcore.location.clock_tracking import (
    gain_recursion,
    position_mse,
    three_satellite_clock_variance,
    tracking_position_errors,
)
from navcore.papers import atc10_clock_tracking, atc10_tracking_geometry, wf_assessment, wf_inputs
from navcore.units import FT, C


@pytest.mark.parametrize("example", ["I", "II"])
@pytest.mark.parametrize("sigma0", [1.0, 5.0, 20.0])
def test_tracking_position_errors_matches_paper_row_and_oracle(example, sigma0):
    """Oracle: the tracker's gain recursion run to convergence (a different algorithm from the
    closed forms: it iterates the filter and is checked against a brute-force covariance and a
    Monte Carlo of the tracker in test_clock_tracking.py): the least-squares error uses the
    first gain 1/beta, the tracking limit the converged gain, and the first three-satellite
    estimate the exact clock variance one epoch after the drop. The paper module's table row
    must be the library's (it delegates)."""
    inputs = atc10_tracking_geometry.printed_table_4_2(example)
    sigma, c = atc10_tracking_geometry.IN.sigma_ns, atc10_tracking_geometry.IN.c_ft_per_ns
    row = tracking_position_errors(
        inputs["trace_all"],
        inputs["s_all"],
        inputs["trace_123"],
        inputs["s_123"],
        inputs["beta"],
        sigma0,
        sigma,
        c=c,
    )
    assert tuple(row) == pytest.approx(atc10_clock_tracking.table_4_3_row(inputs, sigma0), rel=1e-12)
    h = gain_recursion(inputs["beta"], sigma, sigma0, 20_000)
    assert h.gamma[0] == pytest.approx(1.0 / inputs["beta"], rel=1e-12)
    sd0 = c * math.sqrt(position_mse(sigma, inputs["trace_all"], inputs["s_all"], h.gamma[0]))
    sdn = c * math.sqrt(position_mse(sigma, inputs["trace_all"], inputs["s_all"], h.gamma[-1]))
    v3 = float(three_satellite_clock_variance(h.gamma[-1], h.cross[-1], sigma, sigma0, 1))
    sdn1 = c * math.sqrt(sigma**2 * inputs["trace_123"] + v3 * inputs["s_123"])
    assert (row.sd_least_squares, row.sd_tracking_limit, row.sd_first_three_satellite) == pytest.approx(
        (sd0, sdn, sdn1), rel=1e-10
    )
    assert row.alpha == pytest.approx(8 / 27 * sigma0**2 * inputs["beta"] / sigma**2, rel=1e-14)
    assert row.psi == pytest.approx(h.gamma[-1] * inputs["beta"], rel=1e-10)


def test_tracking_position_errors_convention_is_a_parameter():
    """Physical c in SI: sigma in seconds gives metres, the ft/ns convention gives ns numbers."""
    inputs = atc10_tracking_geometry.printed_table_4_2("I")
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
    """The WF module's improvement is the library's (it delegates)."""
    covs = wf_assessment.local_covariances(sigma_a, sigma_t, n_sat)
    reference = math.hypot(wf_inputs.IN.sigma_n, sigma_t)
    assert federated_improvement_db(covs, reference) == pytest.approx(
        wf_assessment.improvement_db(sigma_a, sigma_t, n_sat), abs=1e-12
    )


@pytest.mark.parametrize("sigmas", [(1.0, 2.0), (0.3, 1.5, 4.0)])
def test_federated_improvement_db_isotropic_closed_form(sigmas):
    """Oracle: for isotropic local covariances sigma_i^2 I the per-axis bound of WF Eq. (23)
    is sum_i s_i / sum_i s_i^2 with s_i = 1/sigma_i, so the improvement over a reference
    sigma_r is 20 log10(bound / sigma_r) (closed form; cf. test_wf_assessment.py)."""
    s = 1.0 / np.array(sigmas)
    covs = [sg**2 * np.eye(3) for sg in sigmas]
    expect = 20 * math.log10(s.sum() / (s**2).sum() / 2.5)
    assert federated_improvement_db(covs, 2.5) == pytest.approx(expect, abs=1e-12)


def test_federated_improvement_db_rejects_bad_reference():
    with pytest.raises(ValueError, match="reference_sigma"):
        federated_improvement_db([np.eye(3)], 0.0)
