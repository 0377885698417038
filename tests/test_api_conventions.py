"""One set of conventions and no silent wrong answer (issue 30, items 1 and 5).

Three kinds of test:

- the eleven silent wrong answers and the two raw tracebacks of issue 30, each as a call
  that must now raise naming the argument (or, for the empty Kalman update, be the
  documented no-op);
- a property test over the public API for the *classes* those cases belong to: non-unit
  quaternions, non-orthonormal rotation matrices, non-PSD covariances wherever a covariance
  enters, angles out of range for their unit, and stacks of the wrong depth. hypothesis
  (derandomized) draws the bad value of each class from a valid call of every function
  that takes such an argument; the call must raise ``ValueError`` naming the argument.
  Which functions take such an argument is decided from the parameter names over the whole
  public API (a new function with a ``P``, ``C_bn``, ``lat`` or a rotating ``q`` must be
  registered here or exempted with its reason);
- the conventions: every function with a bare angle argument takes ``deg=`` (keyword-only,
  default False) and converts at its boundary; lines of sight point from the receiver to
  the satellite, receiver first.
"""

from __future__ import annotations

import importlib
import inspect
import math
import re
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_api_inputs import PUBLIC, _parameters

# --------------------------------------------------------------------------------------------
# The eleven silent wrong answers and the two tracebacks of issue 30
# --------------------------------------------------------------------------------------------


def _issue_30_cases() -> list[tuple[str, Callable[[], Any], str]]:
    from navcore.estimation.covariance import Measurement, propagate_covariance
    from navcore.frames import dcm_from_quat, quat_rotate
    from navcore.inertial.error_dynamics import (
        ErrorSources,
        error_dynamics,
        initial_covariance,
        ins_error_layout,
    )
    from navcore.inertial.imu import ImuSpec
    from navcore.inertial.trajectories import straight_and_level
    from navcore.integration.engine import circular_error_probable
    from navcore.location.multilateration import position_dilution

    lay = ins_error_layout("position", "velocity", "misalignment")
    sats = np.array([[2.0e7, 0.0, 0.0], [0.0, 2.0e7, 0.0], [0.0, 0.0, 2.0e7], [1.2e7, 1.6e7, 0.0]])
    return [
        ("1 non-unit quaternion", lambda: quat_rotate([2.0, 0, 0, 0], [1.0, 0, 0]), "q"),
        # 2: a stack of quaternions now gives a stack of matrices (tested below), and a
        # stack of 4-vectors that are not unit quaternions raises
        ("2 stack of non-unit quaternions", lambda: dcm_from_quat(np.tile([2.0, 0, 0, 0], (4, 1))), "q"),
        (
            "3 measurement variance -0.5",
            lambda: propagate_covariance(
                np.eye(1),
                [0.0, 1.0],
                np.eye(1),
                np.eye(1),
                lambda k: [Measurement(np.eye(1), -0.5 * np.eye(1))],
            ),
            "R",
        ),
        (
            "4 Q = -0.5 I",
            lambda: propagate_covariance(np.eye(2), [0.0, 1.0], np.eye(2), -0.5 * np.eye(2)),
            "Q",
        ),
        ("5 positions for lines of sight", lambda: position_dilution(sats), "F"),
        (
            "6 latitude 48 as radians",
            lambda: error_dynamics(lay, f_ned=[0, 0, -9.8], C_bn=np.eye(3), lat=48.0),
            "lat",
        ),
        ("7 C_bn = 2 I", lambda: error_dynamics(lay, f_ned=[0, 0, -9.8], C_bn=2 * np.eye(3)), "C_bn"),
        ("8 lat0 = 48 as radians", lambda: straight_and_level(10.0, speed=100.0, lat0=48.0), "lat0"),
        ("9 CEP of a non-PSD matrix", lambda: circular_error_probable([[1.0, 2.0], [2.0, 1.0]]), "P2"),
        ("10 gyro bias 1 rad/s", lambda: ImuSpec("x", gyro_bias=1.0), "ImuSpec.gyro_bias"),
        (
            "11 negative position sigma",
            lambda: initial_covariance(lay, ErrorSources(imu=ImuSpec("x")), position_sigma=(-10, 10, 10)),
            "position_sigma",
        ),
        ("traceback: (2, 4) stack", lambda: dcm_from_quat(np.ones((2, 4))), "q"),
    ]


@pytest.mark.parametrize(("label", "call", "name"), _issue_30_cases(), ids=[c[0] for c in _issue_30_cases()])
def test_issue_30_cases_raise_naming_the_argument(label, call, name):
    with pytest.raises(ValueError, match=re.escape(name)):
        call()


def test_quaternion_stack_gives_a_matrix_stack():
    """Issue 30, case 2 and the second traceback: stacks (N, 4) give (N, 3, 3)."""
    from navcore.frames import dcm_from_quat

    assert dcm_from_quat(np.tile([1.0, 0, 0, 0], (4, 1))).shape == (4, 3, 3)
    q = np.array([[1.0, 0, 0, 0], [0.0, 0, 0, 1]])
    np.testing.assert_allclose(dcm_from_quat(q)[1], np.diag([-1.0, -1.0, 1.0]), atol=1e-15)


def test_empty_kalman_update_is_a_documented_no_op():
    """An epoch without satellites (z of length 0) returns the prior unchanged, validated or
    not; H and R must then be empty too. The information form does the same."""
    from navcore.estimation.kalman import information_update, kf_update

    x, P = np.array([1.0, 2.0]), np.array([[2.0, 0.5], [0.5, 1.0]])
    for validate in (True, False):
        up = kf_update(x, P, np.zeros(0), np.zeros((0, 2)), np.zeros((0, 0)), validate=validate)
        np.testing.assert_array_equal(up.x, x)
        np.testing.assert_array_equal(up.P, P)
        assert up.K.shape == (2, 0) and up.innovation.shape == (0,) and up.S.shape == (0, 0)
    with pytest.raises(ValueError, match="H and R must be empty"):
        kf_update(x, P, [], np.ones((1, 2)), [[1.0]])
    y, Y = information_update(x, P, [], np.zeros((0, 2)), np.zeros((0, 0)))
    np.testing.assert_array_equal(y, x)
    np.testing.assert_array_equal(Y, P)


# --------------------------------------------------------------------------------------------
# The classes, over the public API
# --------------------------------------------------------------------------------------------
COVARIANCE, QUATERNION, ROTATION, LATITUDE, LONGITUDE, VERTICAL = (
    "covariance",
    "quaternion",
    "rotation",
    "latitude",
    "longitude",
    "vertical angle",
)

_LAY = None


def _layout() -> Any:
    global _LAY
    if _LAY is None:
        from navcore.inertial.error_dynamics import ins_error_layout

        _LAY = ins_error_layout("position", "velocity", "misalignment", "gyro bias", "accel bias")
    return _LAY


def _sources() -> Any:
    from navcore.inertial.error_dynamics import ErrorSources
    from navcore.inertial.imu import ImuSpec

    return ErrorSources(imu=ImuSpec("x", gyro_bias=1e-6, accel_bias=1e-3))


def _p0() -> np.ndarray:
    from navcore.inertial.error_dynamics import initial_covariance

    return initial_covariance(_layout(), _sources(), position_sigma=(1.0, 1.0, 1.0))


def _trajectory() -> Any:
    from navcore.inertial.trajectories import straight_and_level

    return straight_and_level(4.0, speed=50.0, dt=1.0, lat0=0.7)


def _emitter_call() -> dict[str, Any]:
    """The emitter-location example of its docstring, with a weight matrix."""
    from navcore.location.emitter import doppler_frequency

    s = np.linspace(0.0, 1.0, 11)
    p = np.column_stack([2000.0 * s, 500.0 * np.sin(np.pi * s), -1000.0 - 300.0 * s])
    v = np.gradient(p, axis=0) * 10.0
    m = doppler_frequency(1e9, [1000.0, 3000.0, 0.0], p, v)
    return {
        "measurements": m,
        "position": p,
        "velocity": v,
        "initial": [900.0, 2800.0, -100.0, 1e9 + 5.0],
        "W": np.eye(11),
    }


Q1 = np.array([math.cos(0.3), 0.0, 0.0, math.sin(0.3)])
C1 = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
SPD2 = np.array([[2.0, 0.5], [0.5, 1.0]])
SPD3 = np.diag([1.0, 2.0, 3.0])
LOS = np.array([[0.0, 0.0, -1.0], [0.8, 0.0, -0.6], [0.0, 0.8, -0.6], [-0.8, 0.0, -0.6]])

#: function -> (valid keyword arguments, factory so that objects are built lazily),
#: {parameter: class}; ``deg`` marks functions whose angles also take degrees.
REGISTRY: dict[str, tuple[Callable[[], dict[str, Any]], dict[str, str]]] = {
    # frames
    "frames.dcm_from_quat": (lambda: {"q": Q1}, {"q": QUATERNION}),
    "frames.euler_from_quat": (lambda: {"q": np.stack([Q1, Q1])}, {"q": QUATERNION}),
    "frames.quat_rotate": (lambda: {"q": Q1, "v": [1.0, 2.0, 3.0]}, {"q": QUATERNION}),
    "frames.rotvec_from_quat": (lambda: {"q": Q1}, {"q": QUATERNION}),
    "frames.euler_from_dcm": (lambda: {"C_bn": C1}, {"C_bn": ROTATION}),
    "frames.quat_from_dcm": (lambda: {"C": np.stack([C1, np.eye(3)])}, {"C": ROTATION}),
    "frames.dcm_from_euler": (lambda: {"roll": 0.1, "pitch": 0.2, "yaw": 0.3}, {"pitch": VERTICAL}),
    "frames.quat_from_euler": (lambda: {"roll": 0.1, "pitch": [0.2, 0.1], "yaw": 0.3}, {"pitch": VERTICAL}),
    "frames.radii_of_curvature": (lambda: {"lat": 0.5}, {"lat": LATITUDE}),
    "frames.geodetic_to_ecef": (
        lambda: {"lat": [0.5, 0.6], "lon": 0.1, "h": 0.0},
        {"lat": LATITUDE, "lon": LONGITUDE},
    ),
    "frames.dcm_ecef_to_ned": (lambda: {"lat": 0.5, "lon": 0.1}, {"lat": LATITUDE, "lon": LONGITUDE}),
    "frames.dcm_ecef_to_enu": (lambda: {"lat": 0.5, "lon": 0.1}, {"lat": LATITUDE, "lon": LONGITUDE}),
    "frames.ecef_to_ned": (
        lambda: {"r_e": [6.4e6, 0.0, 0.0], "lat0": 0.0, "lon0": 0.0, "h0": 0.0},
        {"lat0": LATITUDE, "lon0": LONGITUDE},
    ),
    "frames.ned_to_ecef": (
        lambda: {"r_n": [1.0, 2.0, 3.0], "lat0": 0.5, "lon0": 0.1, "h0": 0.0},
        {"lat0": LATITUDE, "lon0": LONGITUDE},
    ),
    "frames.ecef_to_enu": (
        lambda: {"r_e": [6.4e6, 0.0, 0.0], "lat0": [0.0, 0.1], "lon0": 0.0, "h0": 0.0},
        {"lat0": LATITUDE, "lon0": LONGITUDE},
    ),
    "frames.enu_to_ecef": (
        lambda: {"r_enu": [1.0, 2.0, 3.0], "lat0": 0.5, "lon0": 0.1, "h0": 0.0},
        {"lat0": LATITUDE, "lon0": LONGITUDE},
    ),
    "frames.geodetic_to_ned": (
        lambda: {"lat": 0.5, "lon": 0.1, "h": 0.0, "lat0": 0.5, "lon0": 0.1, "h0": 10.0},
        {"lat": LATITUDE, "lon": LONGITUDE, "lat0": LATITUDE, "lon0": LONGITUDE},
    ),
    "frames.geodetic_to_enu": (
        lambda: {"lat": 0.5, "lon": 0.1, "h": 0.0, "lat0": 0.5, "lon0": 0.1, "h0": 10.0},
        {"lat": LATITUDE, "lat0": LATITUDE},
    ),
    "frames.ned_to_geodetic": (
        lambda: {"r_n": [1.0, 2.0, 3.0], "lat0": 0.5, "lon0": 0.1, "h0": 0.0},
        {"lat0": LATITUDE, "lon0": LONGITUDE},
    ),
    "frames.enu_to_geodetic": (
        lambda: {"r_enu": [1.0, 2.0, 3.0], "lat0": 0.5, "lon0": 0.1, "h0": 0.0},
        {"lat0": LATITUDE, "lon0": LONGITUDE},
    ),
    "frames.geodetic_to_aer": (
        lambda: {"lat": 0.5, "lon": 0.1, "h": 1000.0, "lat0": 0.5, "lon0": 0.1, "h0": 0.0},
        {"lat": LATITUDE, "lat0": LATITUDE, "lon0": LONGITUDE},
    ),
    "frames.aer_to_geodetic": (
        lambda: {"az": 0.3, "el": 0.2, "srange": 1000.0, "lat0": 0.5, "lon0": 0.1, "h0": 0.0},
        {"el": VERTICAL, "lat0": LATITUDE},
    ),
    "frames.ecef_to_aer": (
        lambda: {"r_e": [6.4e6, 0.0, 0.0], "lat0": 0.0, "lon0": 0.0, "h0": 0.0},
        {"lat0": LATITUDE, "lon0": LONGITUDE},
    ),
    "frames.aer_to_ecef": (
        lambda: {"az": 0.3, "el": 0.2, "srange": 1000.0, "lat0": 0.5, "lon0": 0.1, "h0": 0.0},
        {"el": VERTICAL, "lat0": LATITUDE},
    ),
    "frames.aer_to_enu": (lambda: {"az": 0.3, "el": 0.2, "srange": 1000.0}, {"el": VERTICAL}),
    "frames.aer_to_ned": (lambda: {"az": 0.3, "el": 0.2, "srange": 1000.0}, {"el": VERTICAL}),
    # gravity and GNSS geometry
    "gravity.normal_gravity": (lambda: {"lat": 0.5}, {"lat": LATITUDE}),
    "gravity.free_air_gradient": (lambda: {"lat": 0.5}, {"lat": LATITUDE}),
    "gnss.constellation.elevation_azimuth": (
        lambda: {"r_user": [6.4e6, 0, 0], "r_sat": [[2.6e7, 0, 0]], "lat": 0.0, "lon": 0.0},
        {"lat": LATITUDE, "lon": LONGITUDE},
    ),
    "gnss.constellation.visible": (
        lambda: {
            "constellation": importlib.import_module(
                "navcore.gnss.constellation"
            ).nominal_gps_constellation(),
            "t": 0.0,
            "lat": 0.7,
            "lon": 0.1,
            "h": 0.0,
        },
        {"lat": LATITUDE, "lon": LONGITUDE},
    ),
    "gnss.dop.dilution_of_precision": (
        lambda: {
            "r_receiver": [6.4e6, 0, 0],
            "r_sat": 2.6e7 * np.vstack([[1, 0, 0], 0.6 + 0.4 * np.eye(3)]),
            "mask": 0.1,
        },
        {"mask": VERTICAL},
    ),
    "gnss.dop.satellite_priority": (
        lambda: {
            "r_sat": 2.6e7 * np.vstack([[1, 0, 0], 0.6 + 0.4 * np.eye(3)]),
            "lat": 0.1,
            "lon": 0.1,
            "h": 0.0,
            "mask": 0.1,
        },
        {"lat": LATITUDE, "lon": LONGITUDE, "mask": VERTICAL},
    ),
    "location.multilateration.position_on_sphere": (
        lambda: {"lat": 0.5, "lon": 0.1, "radius": 1.0},
        {"lat": LATITUDE, "lon": LONGITUDE},
    ),
    # inertial
    "inertial.error_dynamics.earth_rate_ned": (lambda: {"lat": 0.5}, {"lat": LATITUDE}),
    "inertial.error_dynamics.transport_rate_ned": (
        lambda: {"v_ned": [10.0, 5.0, 0.0], "lat": 0.5},
        {"lat": LATITUDE},
    ),
    "inertial.strapdown.earth_rate_ned": (lambda: {"lat": 0.5}, {"lat": LATITUDE}),
    "inertial.strapdown.transport_rate_ned": (
        lambda: {"vel": [10.0, 5.0, 0.0], "lat": 0.5, "h": 0.0},
        {"lat": LATITUDE},
    ),
    "inertial.error_dynamics.error_dynamics": (
        lambda: {"layout": _layout(), "f_ned": [0.0, 0.0, -9.8], "C_bn": C1, "lat": 0.5},
        {"lat": LATITUDE, "C_bn": ROTATION},
    ),
    "inertial.error_dynamics.gyrocompass_alignment": (
        lambda: {"P0": _p0(), "layout": _layout(), "lat": 0.5, "C_bn": C1},
        {"P0": COVARIANCE, "lat": LATITUDE, "C_bn": ROTATION},
    ),
    "inertial.error_dynamics.levelling_alignment": (
        lambda: {"P0": _p0(), "layout": _layout(), "heading_sigma": 0.01, "lat": 0.5, "C_bn": C1},
        {"P0": COVARIANCE, "lat": LATITUDE, "C_bn": ROTATION},
    ),
    "inertial.error_model17.error_dynamics_17": (
        lambda: {"C_bn": C1, "f_n": [0.0, 0.0, -9.8]},
        {"C_bn": ROTATION},
    ),
    "inertial.trajectories.fly": (
        lambda: {
            "segments": [importlib.import_module("navcore.inertial.trajectories").Segment(2.0)],
            "lat0": 0.5,
            "lon0": 0.1,
            "path_angle0": 0.05,
        },
        {"lat0": LATITUDE, "lon0": LONGITUDE, "path_angle0": VERTICAL},
    ),
    "inertial.trajectories.straight_and_level": (
        lambda: {"duration": 2.0, "lat0": 0.5, "lon0": 0.1},
        {"lat0": LATITUDE, "lon0": LONGITUDE},
    ),
    "inertial.residual_acceleration.residual_acceleration_covariance": (
        lambda: {"sensitivity": np.ones((3, 6)), "error_covariance": 1e-8 * np.eye(6)},
        {"error_covariance": COVARIANCE},
    ),
    "inertial.residual_acceleration.sphere_probability": (
        lambda: {"cov": SPD3, "radius": 2.0},
        {"cov": COVARIANCE},
    ),
    "inertial.residual_acceleration.sphere_radius": (lambda: {"cov": SPD3}, {"cov": COVARIANCE}),
    "inertial.residual_acceleration.sphere_radius_monte_carlo": (
        lambda: {"cov": SPD3, "n": 100},
        {"cov": COVARIANCE},
    ),
    # GNSS attitude rows
    "integration.measurement_rows.dd_observation_rows": (
        lambda: {
            "los_m": [0.0, 0.0, -1.0],
            "los_n": [1.0, 0.0, 0.0],
            "C_bn": C1,
            "baselines_b": [[1.0, 0.0, 0.0]],
        },
        {"C_bn": ROTATION},
    ),
    "integration.measurement_rows.euler_attitude_rows": (
        lambda: {"C_bn": C1, "roll": 0.1, "pitch": 0.2},
        {"C_bn": ROTATION, "pitch": VERTICAL},
    ),
    "gnss.carrier_phase.euler_rate_matrix_body": (lambda: {"roll": 0.1, "pitch": 0.2}, {"pitch": VERTICAL}),
    "integration.measurement_rows.tc_attitude_observation_matrix": (
        lambda: {"los_ned": LOS, "C_bn": C1, "roll": 0.1, "pitch": 0.2},
        {"C_bn": ROTATION, "pitch": VERTICAL},
    ),
    "integration.measurement_rows.tc_dd_observation_matrix": (
        lambda: {"los_ned": LOS, "C_bn": C1, "baselines_b": np.eye(3)[:2]},
        {"C_bn": ROTATION},
    ),
    # estimation
    "estimation.covariance.Measurement": (lambda: {"H": np.ones((2, 3)), "R": SPD2}, {"R": COVARIANCE}),
    "estimation.covariance.propagate_covariance": (
        lambda: {"P0": SPD2, "t": [0.0, 1.0], "Phi": np.eye(2), "Q": SPD2},
        {"P0": COVARIANCE, "Q": COVARIANCE},
    ),
    "integration.engine.circular_error_probable": (lambda: {"P2": SPD2}, {"P2": COVARIANCE}),
    "integration.engine.run_covariance_analysis": (
        lambda: {
            "trajectory": _trajectory(),
            "truth_layout": _layout(),
            "filter_layout": _layout(),
            "sources": _sources(),
            "P0": _p0(),
            "P0_filter": _p0(),
            "P0_apriori": _p0(),
        },
        {"P0": COVARIANCE, "P0_filter": COVARIANCE, "P0_apriori": COVARIANCE},
    ),
    "estimation.discretize.discretize": (
        lambda: {"F": [[0.0, 1.0], [0.0, 0.0]], "GQGt": SPD2, "dt": 0.5},
        {"GQGt": COVARIANCE},
    ),
    "estimation.kalman.kf_predict": (
        lambda: {"x": [0.0, 1.0], "P": SPD2, "Phi": np.eye(2), "Q": SPD2},
        {"P": COVARIANCE, "Q": COVARIANCE},
    ),
    "estimation.kalman.joseph_update": (
        lambda: {"P": SPD2, "K": np.eye(2), "H": np.eye(2), "R": SPD2},
        {"P": COVARIANCE, "R": COVARIANCE},
    ),
    "estimation.covariance.biased_filter_error_covariance": (
        lambda: {
            "Phi": np.eye(2),
            "Q": SPD2,
            "P0": SPD2,
            "h": [1.0, 0.0],
            "sigma": [1.0, np.nan],
            "bias_sigma": 1.0,
        },
        {"P0": COVARIANCE, "Q": COVARIANCE},
    ),
    "estimation.kalman.kf_update": (
        lambda: {"x": [0.0, 1.0], "P": SPD2, "z": [1.0, 2.0], "H": np.eye(2), "R": SPD2},
        {"P": COVARIANCE, "R": COVARIANCE},
    ),
    "estimation.kalman.information_from_covariance": (
        lambda: {"x": [0.0, 1.0], "P": SPD2},
        {"P": COVARIANCE},
    ),
    "estimation.kalman.covariance_from_information": (
        lambda: {"y": [0.0, 1.0], "Y": SPD2},
        {"Y": COVARIANCE},
    ),
    "estimation.kalman.information_update": (
        lambda: {"y": [0.0, 1.0], "Y": SPD2, "z": [1.0, 2.0], "H": np.eye(2), "R": SPD2},
        {"Y": COVARIANCE, "R": COVARIANCE},
    ),
    "estimation.lmmse.lmmse_with_nuisance": (
        lambda: {
            "F": [[1.0], [0.0], [0.0]],
            "G": [[1.0], [1.0], [1.0]],
            "mu_x": [0.0],
            "P_x": [[1.0]],
            "mu_n": np.zeros(3),
            "P_n": SPD3,
        },
        {"P_x": COVARIANCE, "P_n": COVARIANCE},
    ),
    "estimation.lmmse.lmmse_with_nuisance_information_form": (
        lambda: {"F": [[1.0], [0.0], [0.0]], "G": [[1.0], [1.0], [1.0]], "P_x": [[1.0]], "P_n": SPD3},
        {"P_x": COVARIANCE, "P_n": COVARIANCE},
    ),
    "estimation.federated.accelerometer_predict": (
        lambda: {"x": [1.0, 0.0], "P": SPD2, "accel": [0.5, 0.1], "Q_a": SPD2, "Ts": 0.1},
        {"P": COVARIANCE, "Q_a": COVARIANCE},
    ),
    "estimation.federated.accelerometer_steady_state": (
        lambda: {"Q_a": SPD2, "R_L": SPD2, "Ts": 1.0},
        {"Q_a": COVARIANCE, "R_L": COVARIANCE},
    ),
    "estimation.federated.gps_doppler_covariance": (
        lambda: {"P_prior": SPD2, "H_G": np.eye(2), "R_G": SPD2},
        {"P_prior": COVARIANCE, "R_G": COVARIANCE},
    ),
    "estimation.federated.gps_doppler_update": (
        lambda: {"x_prior": [0.0, 0.0], "P_prior": SPD2, "y_G": [1.0, 2.0], "H_G": np.eye(2), "R_G": SPD2},
        {"P_prior": COVARIANCE, "R_G": COVARIANCE},
    ),
    "estimation.federated.local_velocity_update": (
        lambda: {"x": [0.0, 0.0], "P": SPD2, "y_L": [1.0, 1.0], "R_L": SPD2},
        {"P": COVARIANCE, "R_L": COVARIANCE},
    ),
    "estimation.federated.navigation_mapped_covariance": (
        lambda: {"tau": [[1.0, 2.0]], "P_N": SPD2, "Q_T": [[0.5]]},
        {"P_N": COVARIANCE, "Q_T": COVARIANCE},
    ),
    "estimation.federated.fused_error_covariance": (
        lambda: {"covariances": [[[1.0]], [[1.0]]], "joint": [[1.0, 0.5], [0.5, 1.0]]},
        {"covariances": COVARIANCE, "joint": COVARIANCE},
    ),
    "estimation.federated.feasible_weights": (
        lambda: {"covariances": [SPD2, 4.0 * SPD2]},
        {"covariances": COVARIANCE},
    ),
    "estimation.federated.federated_covariance_bound": (
        lambda: {"covariances": [SPD2, SPD2]},
        {"covariances": COVARIANCE},
    ),
    "estimation.federated.federated_fusion": (
        lambda: {"estimates": [np.ones(2), np.zeros(2)], "covariances": [SPD2, SPD2]},
        {"covariances": COVARIANCE},
    ),
    "estimation.federated.federated_improvement_db": (
        lambda: {"covariances": [0.01 * SPD3, 0.01 * SPD3], "reference_sigma": 0.1},
        {"covariances": COVARIANCE},
    ),
    "estimation.federated.minkowski_trace_bound": (
        lambda: {"covariances": [SPD2, SPD2]},
        {"covariances": COVARIANCE},
    ),
    "estimation.federated.optimal_weights": (
        lambda: {"covariances": [SPD2, 4.0 * SPD2]},
        {"covariances": COVARIANCE},
    ),
    "estimation.federated.fusion_gains": (
        lambda: {"covariances": [SPD2, 4.0 * SPD2]},
        {"covariances": COVARIANCE},
    ),
    "estimation.federated.navigation_mapped_error_samples": (
        lambda: {
            "tau": [[1.0, 2.0]],
            "P_N": SPD2,
            "Q_T": [[0.5]],
            "rng": np.random.default_rng(0),
            "draws": 10,
        },
        {"P_N": COVARIANCE, "Q_T": COVARIANCE},
    ),
    "integration.ekf_ins_gnss.correct_attitude": (
        lambda: {"q": np.stack([Q1, Q1]), "dpsi": np.zeros((2, 3))},
        {"q": QUATERNION},
    ),
    "integration.ekf_ins_gnss.euler_batch": (lambda: {"C": np.stack([C1, np.eye(3)])}, {"C": ROTATION}),
    "integration.ekf_ins_gnss.euler_jacobian_batch": (
        lambda: {"C": np.stack([C1, np.eye(3)])},
        {"C": ROTATION},
    ),
    # location
    "location.emitter.emitter_gauss_newton": (
        lambda: _emitter_call(),
        {"W": COVARIANCE},
    ),
    "location.emitter.linearized_location_error": (
        lambda: {"H": [[1.0, 0.0], [0.0, 2.0], [1.0, 1.0]], "error": [0.1, 0.2, 0.2], "W": SPD3},
        {"W": COVARIANCE},
    ),
    "location.emitter.location_error_covariance": (
        lambda: {"H": [[2.0, 0.0], [0.0, 2.0]], "error_covariance": SPD2, "W": SPD2},
        {"error_covariance": COVARIANCE, "W": COVARIANCE},
    ),
    "location.target_location.target_location_covariance": (
        lambda: {"P_position": SPD3, "P_attitude": 1e-6 * SPD3, "r_target_m": [8000.0, 0.0, 0.0]},
        {"P_position": COVARIANCE, "P_attitude": COVARIANCE},
    ),
}

#: Parameters whose names mark the class but that are not of it, or functions left unchecked
#: on purpose, each with its reason.
EXEMPT: dict[str, str] = {
    "frames.quat_multiply": "quaternion algebra: the Hamilton product of any quaternions",
    "frames.quat_conjugate": "quaternion algebra: the conjugate of any quaternion",
    "frames.quat_normalize": "its job is to make a quaternion unit",
    "inertial.strapdown.quat_multiply_batch": "quaternion algebra in the mechanization's hot loop",
    "inertial.strapdown.dcm_from_quat_batch": (
        "hot-loop helper of the mechanization, documented as unchecked "
        "(frames.dcm_from_quat is the checked one)"
    ),
    "estimation.kalman.symmetrize": "the symmetric part of any square matrix (or stack)",
    "integration.ekf_ins_gnss.sequential_scalar_updates": (
        "inner-loop helper of run_monte_carlo, which checks its scenario at entry (P is a stack per run)"
    ),
}

_COV_NAMES = re.compile(
    r"^(P|P0|P2|Q|R|Y|W|S|GQGt|cov|covariances|joint|error_covariance|P_(?!xn)\w+|Q_\w+|R_\w+)$"
)
_ROT_NAMES = {"C", "C_bn"}
_LAT_NAMES = {"lat", "lat0"}
_QUAT_MODULES = ("frames", "inertial.strapdown", "integration.ekf_ins_gnss")


def _short(name: str) -> str:
    return name.removeprefix("navcore.")


def _marked(short: str, func: Any) -> set[str]:
    """Parameters whose names mark them as a covariance, rotation, latitude or quaternion."""
    out = set()
    for p in _parameters(func):
        if _COV_NAMES.match(p.name) or p.name in _ROT_NAMES or p.name in _LAT_NAMES:
            out.add(p.name)
        if p.name in ("q", "p") and short.startswith(_QUAT_MODULES):
            out.add(p.name)
    return out


def test_every_marked_parameter_is_registered_or_exempt():
    """A public function whose parameter names mark a covariance, a rotation matrix, a
    latitude or a rotating quaternion has its class test here, or a stated exemption."""
    missing = []
    for name, func in PUBLIC:
        short = _short(name)
        if short in EXEMPT:
            continue
        marked = _marked(short, func)
        covered = set(REGISTRY.get(short, (None, {}))[1])
        if short == "integration.engine.circular_error_probable":
            marked.discard("p")  # the probability, not a quaternion
        if short == "location.target_location.target_location_covariance":
            # a cross-covariance: any finite 3x3 (not symmetric); the joint matrix it forms with
            # P_position and P_attitude is what must be PSD, tested below
            marked.discard("P_position_attitude")
        if marked - covered:
            missing.append(f"{short}: {sorted(marked - covered)}")
    assert not missing, f"register these in REGISTRY (or EXEMPT with a reason): {missing}"


def test_target_location_cross_covariance_must_make_a_psd_joint_covariance():
    """Oracle: a cross-covariance larger than the geometric mean of its variances makes the
    joint 6x6 matrix indefinite (|rho| > 1), which no pair of random vectors has."""
    from navcore.location.target_location import target_location_covariance

    with pytest.raises(ValueError, match="joint covariance"):
        target_location_covariance(np.eye(3), 1e-6 * np.eye(3), [8000.0, 0.0, 0.0], 2e-3 * np.eye(3))
    with pytest.raises(ValueError, match="P_position_attitude"):
        target_location_covariance(np.eye(3), 1e-6 * np.eye(3), [8000.0, 0.0, 0.0], np.eye(2))
    ok = target_location_covariance(np.eye(3), 1e-6 * np.eye(3), [8000.0, 0.0, 0.0], 5e-4 * np.eye(3))
    assert np.all(np.linalg.eigvalsh(ok) >= 0)


def _function(short: str) -> Any:
    mod, attr = short.rsplit(".", 1)
    return getattr(importlib.import_module(f"navcore.{mod}"), attr)


def _rng(data: st.DataObject) -> np.random.Generator:
    return np.random.default_rng(data.draw(st.integers(0, 2**32 - 1), label="seed"))


def _bad_covariance(data: st.DataObject, valid: Any) -> Any:
    if isinstance(valid, list) and valid and np.ndim(valid[0]) >= 2:  # a list of covariances
        return [_bad_covariance(data, valid[0]), *valid[1:]]
    arr = np.asarray(valid, dtype=float)
    n = arr.shape[-1]
    rng = _rng(data)
    q, _ = np.linalg.qr(rng.normal(size=(n, n)))
    lam = rng.uniform(0.5, 2.0, n)
    lam[0] = -data.draw(st.floats(0.05, 1.0), label="negative eigenvalue fraction") * lam.max()
    bad = (q * lam) @ q.T
    out = np.array(np.broadcast_to(arr, arr.shape), dtype=float)
    out.reshape(-1, n, n)[0] = 0.5 * (bad + bad.T)
    return out


def _bad_quaternion(data: st.DataObject, valid: Any) -> Any:
    arr = np.array(valid, dtype=float)
    scale = data.draw(st.one_of(st.floats(0.2, 0.99), st.floats(1.01, 5.0)), label="norm")
    arr.reshape(-1, 4)[0] *= scale
    return arr


def _bad_rotation(data: st.DataObject, valid: Any) -> Any:
    arr = np.array(valid, dtype=float)
    kind = data.draw(st.sampled_from(["scaled", "sheared", "reflection"]), label="kind")
    first = arr.reshape(-1, 3, 3)
    if kind == "scaled":
        first[0] *= data.draw(st.one_of(st.floats(0.2, 0.99), st.floats(1.01, 3.0)), label="scale")
    elif kind == "sheared":
        first[0, 0, 1] += data.draw(st.floats(0.01, 1.0), label="shear")
    else:
        first[0] = -first[0]  # orthonormal, det -1
    return arr


def _bad_angle(data: st.DataObject, valid: Any, limit_deg: float, deg: bool) -> Any:
    limit = limit_deg if deg else math.radians(limit_deg)
    beyond = data.draw(st.floats(1.001, 50.0), label="factor beyond the limit") * limit
    value = beyond * data.draw(st.sampled_from([1.0, -1.0]), label="sign")
    if np.ndim(valid) == 0:
        return value
    arr = np.array(valid, dtype=float)
    arr.reshape(-1)[0] = value
    return arr


_LIMIT_DEG = {LATITUDE: 90.0, LONGITUDE: 360.0, VERTICAL: 90.0}
_CASES = [(f, p, c) for f, (_, classes) in REGISTRY.items() for p, c in classes.items()]


def _takes_deg(func: Any) -> bool:
    p = inspect.signature(func).parameters.get("deg")
    return p is not None and p.kind is p.KEYWORD_ONLY


@pytest.mark.parametrize(("short", "param", "klass"), _CASES, ids=[f"{f}-{p}" for f, p, _ in _CASES])
@settings(
    derandomize=True,
    database=None,
    max_examples=8,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
@given(data=st.data())
def test_class_of_bad_value_raises_naming_the_argument(short, param, klass, data):
    """A valid call succeeds; the same call with ``param`` replaced by a bad value of its class
    (and, for an angle, also in degrees with deg=True) raises ValueError naming ``param``."""
    func = _function(short)
    kwargs = REGISTRY[short][0]()
    with np.errstate(all="raise", under="ignore"):
        func(**kwargs)  # the valid call
    variants: list[tuple[dict[str, Any], Any]] = []
    if klass == COVARIANCE:
        variants.append(({}, _bad_covariance(data, kwargs[param])))
    elif klass == QUATERNION:
        variants.append(({}, _bad_quaternion(data, kwargs[param])))
    elif klass == ROTATION:
        variants.append(({}, _bad_rotation(data, kwargs[param])))
    else:
        variants.append(({}, _bad_angle(data, kwargs[param], _LIMIT_DEG[klass], deg=False)))
        if _takes_deg(func):
            valid_deg = np.degrees(kwargs[param])
            variants.append(({"deg": True}, _bad_angle(data, valid_deg, _LIMIT_DEG[klass], deg=True)))
    for extra, bad in variants:
        call = {**kwargs, **extra, param: bad}
        with pytest.raises(ValueError, match=re.escape(param)):
            func(**call)


_DEPTH = [(f, p, c) for f, p, c in _CASES if c in (COVARIANCE, QUATERNION, ROTATION)]
#: Arguments documented as stacks ``(..., 4)``, ``(..., 3, 3)`` or ``(B, n, n)``: a leading
#: axis is allowed there, and only a wrong trailing shape must raise.
STACKS = {
    ("frames.dcm_from_quat", "q"),
    ("frames.euler_from_quat", "q"),
    ("frames.quat_rotate", "q"),
    ("frames.rotvec_from_quat", "q"),
    ("frames.euler_from_dcm", "C_bn"),
    ("frames.quat_from_dcm", "C"),
    ("integration.ekf_ins_gnss.correct_attitude", "q"),
    ("integration.ekf_ins_gnss.euler_batch", "C"),
    ("integration.ekf_ins_gnss.euler_jacobian_batch", "C"),
    ("estimation.discretize.discretize", "GQGt"),
    ("estimation.kalman.joseph_update", "P"),
    ("estimation.kalman.joseph_update", "R"),
    ("inertial.error_model17.error_dynamics_17", "C_bn"),
    ("integration.engine.run_covariance_analysis", "P0"),
    ("integration.engine.run_covariance_analysis", "P0_filter"),
    ("integration.engine.run_covariance_analysis", "P0_apriori"),
}


@pytest.mark.parametrize(("short", "param", "klass"), _DEPTH, ids=[f"{f}-{p}" for f, p, _ in _DEPTH])
def test_stack_of_the_wrong_depth_raises_naming_the_argument(short, param, klass):
    """A quaternion that does not end in 4 or a matrix that does not end in (3, 3) or
    (n, n); and, where a function takes one matrix, a stack of two: ValueError naming it."""
    func = _function(short)
    kwargs = REGISTRY[short][0]()
    valid = kwargs[param]
    if isinstance(valid, list) and valid and np.ndim(valid[0]) >= 2:
        bad_values = [[np.stack([np.asarray(valid[0], float)] * 2), *valid[1:]]]
    else:
        arr = np.asarray(valid, dtype=float)
        bad_values = [arr[..., :-1]]  # the last axis one short
        if klass != QUATERNION:
            bad_values.append(arr[..., :-1, :])  # a row short
            if (short, param) not in STACKS:
                bad_values.append(np.stack([arr, arr]))  # a stack where one matrix is expected
    for bad in bad_values:
        with pytest.raises(ValueError, match=re.escape(param)):
            func(**{**kwargs, param: bad})


# --------------------------------------------------------------------------------------------
# Conventions: deg= wherever a bare angle enters; lines of sight receiver -> satellite
# --------------------------------------------------------------------------------------------
_ANGLE_NAMES = {
    "lat",
    "lon",
    "lat0",
    "lon0",
    "roll",
    "pitch",
    "yaw",
    "heading",
    "heading0",
    "path_angle0",
    "az",
    "el",
    "angle",
    "mask",
    "cone_half_angle",
}


def test_every_bare_angle_argument_comes_with_deg():
    """Convention (package docstring): an angle parameter without a unit in its name is in
    radians, and its function has a keyword-only ``deg: bool = False``."""
    lacking = []
    for name, func in PUBLIC:
        if inspect.isclass(func):
            continue
        params = inspect.signature(func).parameters
        angles = _ANGLE_NAMES & set(params)
        if not angles:
            continue
        deg = params.get("deg")
        if deg is None or deg.kind is not deg.KEYWORD_ONLY or deg.default is not False:
            lacking.append(f"{_short(name)} ({', '.join(sorted(angles))})")
    assert not lacking, f"functions with angles but no keyword-only deg=False: {lacking}"


@pytest.mark.parametrize(
    ("short", "kwargs", "angles"),
    [
        ("frames.geodetic_to_ecef", {"lat": 0.7, "lon": -1.2, "h": 100.0}, ("lat", "lon")),
        ("frames.dcm_from_euler", {"roll": 0.1, "pitch": -0.2, "yaw": 2.5}, ("roll", "pitch", "yaw")),
        ("gnss.constellation.elevation_azimuth", None, ("lat", "lon")),
        (
            "location.multilateration.position_on_sphere",
            {"lat": 0.4, "lon": 2.0, "radius": 3.0},
            ("lat", "lon"),
        ),
        ("inertial.error_dynamics.earth_rate_ned", {"lat": 0.9}, ("lat",)),
        (
            "inertial.strapdown.transport_rate_ned",
            {"vel": [50.0, 20.0, 0.0], "lat": 0.9, "h": 10.0},
            ("lat",),
        ),
        ("gravity.normal_gravity", {"lat": 0.9, "h": 100.0}, ("lat",)),
        (
            "inertial.trajectories.straight_and_level",
            {"duration": 3.0, "speed": 10.0, "heading": 1.0, "lat0": 0.5, "lon0": 0.2},
            ("heading", "lat0", "lon0"),
        ),
    ],
)
def test_deg_true_is_the_same_call_in_degrees(short, kwargs, angles):
    """Oracle: the same function in radians: deg=True with the angles in degrees gives the
    same result (numbers alike; angles returned in degrees where the function returns any)."""
    func = _function(short)
    if kwargs is None:
        from navcore.frames import geodetic_to_ecef

        kwargs = {
            "r_user": geodetic_to_ecef(0.6, 0.2, 0.0),
            "r_sat": [[2.0e7, 1.0e7, 1.5e7]],
            "lat": 0.6,
            "lon": 0.2,
        }
    rad = func(**kwargs)
    deg = func(**{**kwargs, **{a: np.degrees(kwargs[a]) for a in angles}, "deg": True})
    if short == "gnss.constellation.elevation_azimuth":
        np.testing.assert_allclose(np.degrees(rad), deg, rtol=1e-12)
    elif short == "inertial.trajectories.straight_and_level":
        np.testing.assert_allclose(rad.pos_ned, deg.pos_ned, rtol=1e-12, atol=1e-9)
        np.testing.assert_allclose(rad.lat, deg.lat, rtol=1e-12)
    else:
        np.testing.assert_allclose(rad, deg, rtol=1e-12, atol=1e-15)


def test_lines_of_sight_point_from_the_receiver_to_the_satellite():
    """Convention: the receiver (user, aircraft) is the first argument and the unit vectors
    point from it to each satellite, in navcore.gnss and navcore.location alike."""
    from navcore.gnss.constellation import line_of_sight
    from navcore.location.multilateration import line_of_sight_matrix

    receiver = np.array([6.4e6, 0.0, 0.0])
    sats = np.array([[2.6e7, 0.0, 0.0], [1.0e7, 1.5e7, 1.0e7]])
    u, _ = line_of_sight(receiver, sats)
    expected = (sats - receiver) / np.linalg.norm(sats - receiver, axis=1)[:, None]
    np.testing.assert_allclose(u, expected, rtol=1e-15)
    np.testing.assert_allclose(line_of_sight_matrix(receiver, sats), expected, rtol=1e-15)
    assert list(inspect.signature(line_of_sight).parameters)[:2] == ["r_user", "r_sat"]
    assert list(inspect.signature(line_of_sight_matrix).parameters)[:2] == ["aircraft", "satellites"]


def test_schedules_are_functions_of_the_step_index():
    """Convention: a measurement schedule is ``k -> measurements`` in both covariance engines."""
    from navcore.estimation.covariance import Measurement, propagate_covariance

    seen = []

    def schedule(k):
        seen.append(k)
        return [Measurement(np.eye(1), np.eye(1))]

    propagate_covariance(np.eye(1), [0.0, 1.0, 2.0], np.eye(1), np.eye(1), schedule)
    assert seen == [0, 1, 2]
