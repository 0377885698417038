"""Tests of the WF Sec. IV.D scenario and the worked example against closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from navcore.papers import wf
from navcore.papers import wf_example as ex


@pytest.mark.parametrize("sigma_a", [1e-5, 1e-4, 1e-3, 1e-2])
@pytest.mark.parametrize("sigma_t", wf.SIGMA_T)
def test_two_estimator_bound_closed_form(sigma_a, sigma_t):
    """Oracle: two isotropic estimators give the per-axis bound (s1 + s2)/(s1^2 + s2^2), s_i = 1/sigma_i.

    sigma_DL comes from the closed-form random-walk steady state P+ = (-q + sqrt(q^2 + 4 q r))/2.
    """
    q, r = (sigma_a * wf.TS) ** 2, (200 * sigma_a) ** 2
    s_dl = np.sqrt((-q + np.sqrt(q * q + 4 * q * r)) / 2)
    s_dn = np.hypot(wf.SIGMA_N, sigma_t)
    s1, s2 = 1 / s_dn, 1 / s_dl
    assert wf.sigma_d_bound(sigma_a, sigma_t) == pytest.approx((s1 + s2) / (s1**2 + s2**2), rel=1e-10)


def test_improvement_small_sigma_a_asymptote():
    """Oracle: sigma_DL << sigma_DN gives 20 log10(2 s * sigma_a / sigma_DN) (Sec. IV.D straight lines)."""
    sa = 1e-5
    expected = 20 * np.log10(2.0 * sa / np.hypot(0.02, 2.0))
    assert wf.improvement_db(sa, 2.0) == pytest.approx(expected, abs=0.01)


def test_local_covariances_reject_bad_satellite_count():
    """Validation: Eq. (25) has 1 or 3 satellites only."""
    with pytest.raises(ValueError, match="n_sat"):
        wf.local_covariances(1e-3, 2.0, n_sat=2)


def test_worked_example_federated_matches_true_velocity():
    """Oracle: with velocity errors far below sigma_f/(f0/c), WF Eq. (6) says the location error is set by
    the frequency noise alone, so the federated case must match the true-velocity case closely."""
    r = ex.run()
    e_true, e_fed, e_nav = (r["errors"][k] for k in ("true", "federated", "navigation"))
    assert np.sqrt(np.mean(r["vel_err"]["federated"] ** 2)) < 0.01
    np.testing.assert_allclose(e_fed, e_true, atol=2.0)
    assert np.sqrt(np.mean(e_nav[:, :2] ** 2)) > 3 * np.sqrt(np.mean(e_true[:, :2] ** 2))
