"""Tests of the WF Sec. IV.D scenario and the worked example against closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from navcore.papers import wf_aperture_velocity, wf_assessment, wf_inputs
from navcore.papers import wf_example as ex


@pytest.mark.parametrize("sigma_a", [1e-5, 1e-4, 1e-3, 1e-2])
@pytest.mark.parametrize("sigma_t", wf_inputs.sigma_t_values())
def test_two_estimator_bound_closed_form(sigma_a, sigma_t):
    """Oracle: two isotropic estimators give the per-axis bound (s1 + s2)/(s1^2 + s2^2), s_i = 1/sigma_i.

    sigma_DL comes from the closed-form random-walk steady state P+ = (-q + sqrt(q^2 + 4 q r))/2.
    """
    q, r = (sigma_a * wf_inputs.IN.ts) ** 2, (200 * sigma_a) ** 2
    s_dl = np.sqrt((-q + np.sqrt(q * q + 4 * q * r)) / 2)
    s_dn = np.hypot(wf_inputs.IN.sigma_n, sigma_t)
    s1, s2 = 1 / s_dn, 1 / s_dl
    assert wf_assessment.sigma_d_bound(sigma_a, sigma_t) == pytest.approx(
        (s1 + s2) / (s1**2 + s2**2), rel=1e-10
    )


def test_improvement_small_sigma_a_asymptote():
    """Oracle: sigma_DL << sigma_DN gives 20 log10(2 s * sigma_a / sigma_DN) (Sec. IV.D straight lines)."""
    sa = 1e-5
    expected = 20 * np.log10(2.0 * sa / np.hypot(0.02, 2.0))
    assert wf_assessment.improvement_db(sa, 2.0) == pytest.approx(expected, abs=0.01)


def test_local_covariances_reject_bad_satellite_count():
    """Validation: Eq. (25) has 1 or 3 satellites only."""
    with pytest.raises(ValueError, match="n_sat"):
        wf_assessment.local_covariances(1e-3, 2.0, n_sat=2)


def test_worked_example_federated_matches_true_velocity():
    """Oracle: with velocity errors far below sigma_f/(f0/c), WF Eq. (6) says the location error is set by
    the frequency noise alone, so the federated case must match the true-velocity case closely."""
    r = ex.run()
    e_true, e_fed, e_nav = (r["errors"][k] for k in ("true", "federated", "navigation"))
    assert np.sqrt(np.mean(r["vel_err"]["federated"] ** 2)) < 0.01
    np.testing.assert_allclose(e_fed, e_true, atol=2.0)
    assert np.sqrt(np.mean(e_nav[:, :2] ** 2)) > 3 * np.sqrt(np.mean(e_true[:, :2] ** 2))


@pytest.mark.parametrize("sigma_a", [1e-5, 1e-3, 1e-2])
@pytest.mark.parametrize("sigma_t", wf_inputs.sigma_t_values())
def test_three_satellite_bound_is_weighted_mean_of_sigmas(sigma_a, sigma_t):
    """Oracle: closed forms of WF Eqs. (14) and (17); with isotropic P_i the per-axis bound of Eq. (23) is
    sum_i s_i / sum_i s_i^2 (s_i = 1/sigma_i), the mean of the sigma_i weighted by s_i^2 (premise of the
    WF-fig2-order slack)."""
    q, r = (sigma_a * wf_inputs.IN.ts) ** 2, (200 * sigma_a) ** 2
    post = (-q + np.sqrt(q * q + 4 * q * r)) / 2
    prior = post + q
    f_over_c = 5.25  # the printed f_o^L1/c of Sec. IV.D, the gain of H_G in Eq. (25)
    var_dg = 1 / (1 / prior + f_over_c**2 / wf_inputs.IN.sigma_g**2)
    s = 1 / np.sqrt([wf_inputs.IN.sigma_n**2 + sigma_t**2, post, var_dg])
    assert wf_assessment.sigma_d_bound(sigma_a, sigma_t, 3) == pytest.approx(s.sum() / (s**2).sum(), rel=1e-9)


def test_prior_gap_closed_form():
    """Oracle: 10 log10(1 + q/P+) with the closed-form steady state, largest over the figures' grid."""
    grid = np.logspace(np.log10(wf_inputs.IN.sigma_a_low), np.log10(wf_inputs.IN.sigma_a_high), 31)
    q = (grid * wf_inputs.IN.ts) ** 2
    post = (-q + np.sqrt(q * q + 4 * q * (200 * grid) ** 2)) / 2
    assert wf_assessment.accelerometer_prior_gap_db() == pytest.approx(
        np.max(10 * np.log10(1 + q / post)), rel=1e-9
    )


def test_gps_doppler_velocity_sigma():
    """Oracle: arithmetic sigma_G / (f_L1/c) with the printed f_L1/c = 5.25 1/m (Sec. IV.D), and the
    physical ratio 1575.42 MHz / c within the 0.1 % that the printed digits leave."""
    assert wf_assessment.gps_doppler_velocity_sigma() == pytest.approx(1.0 / 5.25, rel=1e-12)
    assert wf_assessment.gps_doppler_velocity_sigma() == pytest.approx(299_792_458.0 / 1575.42e6, rel=1e-3)


def test_location_leverage_position_bias_is_a_translation():
    """Oracle: WF Eq. (1) depends on p^e - p only: a constant 1 m aperture-position error moves the emitter
    estimate by 1 m (to second order), whatever its direction."""
    np.testing.assert_allclose(wf_aperture_velocity.location_error_leverage()["bias_p"], 1.0, atol=1e-3)
