"""KZL stand-alone IMU from the covariance engine, against independent oracles.

Oracles: the seeded nonlinear strapdown Monte Carlo of the same flight (a different model:
100 Hz quaternion mechanization on a flat Earth, sampled IMU errors) and the closed-form growth
of a gyro bias and angle random walk. (The unit tests of the gyro-bias calibration and of the
levelling alignment are with the inertial package's tests.)
"""

from __future__ import annotations

import numpy as np
import pytest

from navcore.papers import kzl_covariance as kc
from navcore.papers.kzl_scenario import IN, N_RUNS, monte_carlo
from navcore.papers.kzl_simulation import heading_closed_form_deg, t_end
from navcore.units import DEG


@pytest.mark.parametrize("initialise", [True, False])
def test_heading_follows_the_closed_form(initialise):
    """Oracle: sqrt((b t)^2 + N^2 t + sigma0^2) for a constant bias b and angle random walk N."""
    got = kc.standalone_sigma("misalignment", initialise)[2]
    want = heading_closed_form_deg(180.0, calibrated=initialise)
    assert got == pytest.approx(want, rel=2e-3)


def test_engine_agrees_with_the_strapdown_monte_carlo():
    """Oracle: the nonlinear 100 Hz strapdown Monte Carlo of the same flight. Its RMS over
    N_RUNS runs has a relative standard error 1/sqrt(2 N); allow three of them."""
    tol = 3 / np.sqrt(2 * N_RUNS)
    T_END = t_end()
    mc = monte_carlo("ins")
    for block, name in (("position", "pos_err"), ("velocity", "vel_err")):
        engine = kc.standalone_sigma(block)[:2]
        assert mc.rms(name)[T_END, :2] == pytest.approx(engine, rel=tol), block
    assert mc.rms("att_err")[T_END, 2] / DEG == pytest.approx(kc.standalone_sigma("misalignment")[2], rel=tol)
    mc_raw = monte_carlo("ins", False)
    assert mc_raw.rms("att_err")[T_END, 2] / DEG == pytest.approx(
        kc.standalone_sigma("misalignment", False)[2], rel=tol
    )


def test_longer_averaging_gives_smaller_errors():
    """The calibration residual N/sqrt(T) falls with T, and so does every 180-s error."""
    lo, hi = IN.input("init_time_s").low, IN.input("init_time_s").high
    short, nominal, long = (kc.standalone_sigma("velocity", True, t)[0] for t in (lo, IN.init_time_s, hi))
    assert short > nominal > long


@pytest.mark.parametrize("mode", ["tc", "tc_att", "tc_dd"])
def test_heading_observability_is_the_row_space_test(mode):
    """Oracle: the heading's unit vector e lies in the row space of the observability matrix
    [H; HF; ...; HF^16] exactly when the least-squares residual of e against those rows (each
    normalised) is zero; ``heading_observable`` decides it from two observability ranks."""
    from navcore.inertial.error_model17 import ERROR_LAYOUT_17
    from navcore.papers import kzl_tightly_coupled_filter as km

    for nu in (2, 4, 8):
        F, C, los = km.table1_F(), km.table1_attitude(), km.table1_los(nu)
        if mode == "tc":
            H = km.code_doppler_rows(los)
        elif mode == "tc_att":
            H = km.tc_attitude_observation_matrix(los, C, 0.0, 0.0)
        else:
            H = km.tc_dd_observation_matrix(los, C, km.table1_baselines_b())
        rows = [np.atleast_2d(H) @ np.linalg.matrix_power(F, k) for k in range(F.shape[0])]
        O_ = np.vstack(rows)
        O_ = O_[np.linalg.norm(O_, axis=1) > 0]
        O_ = O_ / np.linalg.norm(O_, axis=1)[:, None]
        e = np.zeros(F.shape[0])
        e[ERROR_LAYOUT_17.slice("misalignment").start + 2] = 1.0
        c = np.linalg.lstsq(O_.T, e, rcond=1e-9)[0]
        in_row_space = np.linalg.norm(O_.T @ c - e) < 1e-6
        assert km.heading_observable(mode, nu) == in_row_space, (mode, nu)
