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
