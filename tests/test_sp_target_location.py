"""Target location error over a lever arm against independent oracles."""

from __future__ import annotations

import numpy as np
import pytest

from navcore.frames import dcm_from_euler
from navcore.location import target_location as tl


def test_small_rotation_of_the_line_of_sight() -> None:
    """Oracle: rotate the 8-km line of sight by a small DCM (frames.dcm_from_euler), difference it."""
    r = np.array([8000.0, 3000.0, -200.0])
    angles = np.array([1e-5, -2e-5, 3e-5])
    rotated = dcm_from_euler(*angles) @ r
    err = tl.target_location_error(np.zeros(3), angles, r)
    # first-order: C(alpha) r - r = alpha x r; compare to second order in the angles
    np.testing.assert_allclose(err, rotated - r, atol=np.linalg.norm(r) * 1e-9)


def test_covariance_against_seeded_monte_carlo() -> None:
    """Oracle: seeded Monte Carlo (seed 11, 4e5 draws) of dr + dalpha x r."""
    rng = np.random.default_rng(11)
    Pr = np.diag([100.0**2, 80.0**2, 20.0**2])
    Pa = np.diag([1e-3, 2e-3, 5e-3]) ** 2
    r = np.array([8000.0, 0.0, 0.0])
    n = 400_000
    dr = rng.standard_normal((n, 3)) * np.sqrt(np.diag(Pr))
    da = rng.standard_normal((n, 3)) * np.sqrt(np.diag(Pa))
    e = tl.target_location_error(dr, da, r)
    C = tl.target_location_covariance(Pr, Pa, r)
    d = np.sqrt(np.diag(C))
    sampling_sd = np.sqrt((np.outer(d, d) ** 2 + C**2) / n)  # standard error of a sample covariance
    assert np.all(np.abs(np.cov(e.T) - C) < 5 * sampling_sd)


def test_rss_and_pointing() -> None:
    assert tl.pointing_error_m(1e-3, 8000.0) == pytest.approx(8.0)
    assert tl.target_location_rss(6.0, 1e-3, 8000.0) == pytest.approx(10.0)


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: tl.target_location_error([1.0, 2.0], [0, 0, 0], [1, 0, 0]), "dr_vehicle_m"),
        (lambda: tl.pointing_error_m(-1.0, 8000.0), "misalignment_rad"),
        (lambda: tl.target_location_covariance(np.eye(2), np.eye(3), [1, 0, 0]), "P_position must be 3x3"),
        # each covariance is checked for its shape on its own, the other one being right
        (lambda: tl.target_location_covariance(np.eye(3), np.eye(2), [1, 0, 0]), "P_attitude must be 3x3"),
        (lambda: tl.target_location_covariance(np.eye(3), np.eye(3), [1, 0]), "r_target_m must have a"),
    ],
)
def test_bad_input_raises(call, match) -> None:
    with pytest.raises(ValueError, match=match):
        call()


def test_pointing_error_arrays_and_integer_inputs() -> None:
    """Oracle: arc length r theta by hand, elementwise; integer inputs give floats."""
    out = tl.pointing_error_m(np.array([1, 2]), np.array([8000, 500]))
    assert out.dtype == np.float64
    np.testing.assert_allclose(out, [8000.0, 1000.0])
    assert type(tl.pointing_error_m(1e-3, 8000.0)) is float  # a Python float, not numpy's


def _dead_reckoning_covariance():
    """A joint (position, velocity, psi) covariance with the strong position-heading correlation
    of a dead-reckoned vehicle: an east position error made by a heading error."""
    from navcore.inertial.error_dynamics import ins_error_layout

    lay = ins_error_layout("position", "velocity", "misalignment")
    rng = np.random.default_rng(5)
    A = np.diag([60.0, 60.0, 10.0, 0.3, 0.3, 0.1, 4e-4, 4e-4, 8e-3])
    A[1, 8] = 150.0 / 8e-3 * 8e-3  # east position loaded on the heading error (150 m per 8 mrad)
    L = A + 0.05 * rng.standard_normal((9, 9)) * np.sqrt(np.outer(np.diag(A), np.diag(A)))
    return lay, L @ L.T


def test_target_location_sigma_against_a_monte_carlo_of_the_physical_chain() -> None:
    """Oracle: seeded Monte Carlo (seed 3, 2e5 draws) of the physical chain in the engine's own
    attitude convention (C_hat = exp(-[psi x]) C, the rotation of which the F matrix's
    -psi x f is the linearisation): draw (dr, psi) from the joint covariance, perturb the
    vehicle's position and attitude, locate a target 8 km away from its lever arm measured in
    body axes, and take the sample covariance of the located target's horizontal error. The
    mission code must give its rss within the sampling error; with the attitude error entering
    as dr + psi x r (the wrong sign of the cross-covariance) it was 11 % low here."""
    from types import SimpleNamespace

    from scipy.spatial.transform import Rotation

    from navcore.papers import sp_mission_flights as sc

    lay, P = _dead_reckoning_covariance()
    rng = np.random.default_rng(3)
    n = 200_000
    x = rng.multivariate_normal(np.zeros(lay.size), P, size=n, method="eigh")
    dr, psi = x[:, lay.slice("position")], x[:, lay.slice("misalignment")]
    C = Rotation.from_euler("ZYX", [0.7, 0.05, -0.1]).as_matrix()  # true body-to-NED attitude
    bearing = 30.0
    r_n = 8000.0 * np.array([np.cos(np.radians(bearing)), np.sin(np.radians(bearing)), 0.0])
    r_b = C.T @ r_n  # the lever arm the vehicle measures in its own axes
    C_hat = Rotation.from_rotvec(-psi).as_matrix() @ C  # (n, 3, 3) computed attitudes
    located = dr + C_hat @ r_b  # computed position + computed attitude x lever arm, from p = 0
    err = located - r_n
    mc = float(np.sqrt(np.trace(np.cov(err[:, :2].T))))
    result = SimpleNamespace(snapshots={0: P}, truth_layout=lay)
    book = sc.target_location_sigma(result, range_m=8000.0, bearing_deg=bearing)
    # the rss of 2e5 draws has a relative sampling sd below 0.3 %
    assert book == pytest.approx(mc, rel=0.01)


def test_covariance_with_cross_covariance_against_seeded_monte_carlo() -> None:
    """Oracle: seeded Monte Carlo (seed 13, 4e5 draws) of dr + dalpha x r with correlated
    position and attitude errors; without the cross-covariance argument the errors are
    treated as uncorrelated (the documented default)."""
    rng = np.random.default_rng(13)
    L = np.tril(rng.standard_normal((6, 6))) * np.r_[[50.0] * 3, [2e-3] * 3][:, None]
    P = L @ L.T
    r = np.array([5000.0, -6000.0, 300.0])
    n = 400_000
    x = rng.multivariate_normal(np.zeros(6), P, size=n, method="eigh")
    e = tl.target_location_error(x[:, :3], x[:, 3:], r)
    C = tl.target_location_covariance(P[:3, :3], P[3:, 3:], r, P[:3, 3:])
    d = np.sqrt(np.diag(C))
    sampling_sd = np.sqrt((np.outer(d, d) ** 2 + C**2) / n)
    assert np.all(np.abs(np.cov(e.T) - C) < 5 * sampling_sd)
    uncorrelated = tl.target_location_covariance(P[:3, :3], P[3:, 3:], r)
    assert np.any(np.abs(uncorrelated - C) > 20 * sampling_sd)


def test_cross_covariance_must_make_a_joint_covariance() -> None:
    with pytest.raises(ValueError, match="P_position_attitude must be 3x3"):
        tl.target_location_covariance(np.eye(3), np.eye(3), [1.0, 0, 0], np.eye(2))
    with pytest.raises(ValueError, match="joint covariance"):
        tl.target_location_covariance(np.eye(3), np.eye(3), [1.0, 0, 0], 2.0 * np.eye(3))
