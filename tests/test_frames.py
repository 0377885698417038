"""Frames: rotations, Hamilton quaternions, Euler angles, geodesy.

Oracles: pymap3d (an independent geodesy implementation) for geodetic/ECEF/NED; scipy's
Rotation for quaternion and Euler conventions (scipy is scalar-last: converted explicitly);
algebraic identities (orthogonality, cross product).
"""

from __future__ import annotations

import numpy as np
import pymap3d
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from navcore import frames as fr

angles = st.floats(-np.pi, np.pi, allow_nan=False)
pitches = st.floats(-1.5, 1.5, allow_nan=False)


def test_skew_is_cross_product():
    rng = np.random.default_rng(0)
    a, b = rng.normal(size=(2, 3))
    np.testing.assert_allclose(fr.skew(a) @ b, np.cross(a, b))
    np.testing.assert_allclose(fr.skew(a), -fr.skew(a).T)


@settings(max_examples=60, deadline=None)
@given(angles, pitches, angles)
def test_euler_dcm_against_scipy(roll, pitch, yaw):
    """Oracle: scipy Rotation 'ZYX' intrinsic = yaw, pitch, roll (3-2-1), body to nav."""
    C = fr.dcm_from_euler(roll, pitch, yaw)
    ref = Rotation.from_euler("ZYX", [yaw, pitch, roll]).as_matrix()
    np.testing.assert_allclose(C, ref, atol=1e-12)
    np.testing.assert_allclose(C @ C.T, np.eye(3), atol=1e-12)
    r2, p2, y2 = fr.euler_from_dcm(C)
    np.testing.assert_allclose(fr.dcm_from_euler(r2, p2, y2), C, atol=1e-12)


@settings(max_examples=60, deadline=None)
@given(angles, pitches, angles)
def test_quaternion_matches_scipy_and_dcm(roll, pitch, yaw):
    """Oracle: scipy's quaternion (x, y, z, w) reordered to scalar-first, up to sign."""
    q = fr.quat_from_euler(roll, pitch, yaw)
    ref = Rotation.from_euler("ZYX", [yaw, pitch, roll]).as_quat()  # scalar last
    ref = np.roll(ref, 1)
    if ref[0] < 0:
        ref = -ref
    np.testing.assert_allclose(q, ref, atol=1e-12)
    np.testing.assert_allclose(fr.dcm_from_quat(q), fr.dcm_from_euler(roll, pitch, yaw), atol=1e-12)
    np.testing.assert_allclose(fr.quat_from_dcm(fr.dcm_from_quat(q)), q, atol=1e-12)


def test_hamilton_product_convention():
    """Hamilton: i*j = k (not -k, which would be the JPL convention)."""
    i = np.array([0.0, 1, 0, 0])
    j = np.array([0.0, 0, 1, 0])
    np.testing.assert_allclose(fr.quat_multiply(i, j), [0, 0, 0, 1])
    # composition: q_ab ⊗ q_bc corresponds to C_ab @ C_bc
    rng = np.random.default_rng(3)
    qa, qb = fr.quat_normalize(rng.normal(size=(2, 4)))
    np.testing.assert_allclose(
        fr.dcm_from_quat(fr.quat_multiply(qa, qb)), fr.dcm_from_quat(qa) @ fr.dcm_from_quat(qb), atol=1e-12
    )


def test_quat_rotate_and_rotvec():
    """Oracle: scipy Rotation.from_rotvec applied to a vector."""
    rng = np.random.default_rng(4)
    rv = rng.normal(size=3)
    v = rng.normal(size=3)
    q = fr.quat_from_rotvec(rv)
    np.testing.assert_allclose(fr.quat_rotate(q, v), Rotation.from_rotvec(rv).apply(v), atol=1e-12)
    np.testing.assert_allclose(fr.rotvec_from_quat(q), rv, atol=1e-12)
    # small-angle branch
    tiny = np.array([1e-10, -2e-10, 3e-10])
    np.testing.assert_allclose(fr.rotvec_from_quat(fr.quat_from_rotvec(tiny)), tiny, rtol=1e-6)


def test_geodetic_ecef_against_pymap3d():
    """Oracle: pymap3d.geodetic2ecef / ecef2geodetic (WGS-84)."""
    lats = np.array([0.0, 51.0, -33.9, 89.9, -89.99])
    lons = np.array([0.0, 8.0, 151.2, -120.0, 45.0])
    hs = np.array([0.0, 3000.0, -50.0, 20_200e3, 35_786e3])
    r = fr.geodetic_to_ecef(lats, lons, hs, deg=True)
    ref = np.stack(pymap3d.geodetic2ecef(lats, lons, hs), axis=-1)
    np.testing.assert_allclose(r, ref, atol=1e-6)
    lat, lon, h = fr.ecef_to_geodetic(r, deg=True)
    np.testing.assert_allclose(lat, lats, atol=1e-9)
    np.testing.assert_allclose(lon, lons, atol=1e-9)
    np.testing.assert_allclose(h, hs, atol=1e-4)


def test_ned_against_pymap3d():
    """Oracle: pymap3d.ecef2ned / ned2ecef."""
    lat0, lon0, h0 = 51.0, 8.0, 3000.0
    pts = fr.geodetic_to_ecef(
        np.array([51.1, 50.9]), np.array([8.2, 7.9]), np.array([2000.0, 9000.0]), deg=True
    )
    ned = fr.ecef_to_ned(pts, lat0, lon0, h0, deg=True)
    ref = np.stack(pymap3d.ecef2ned(pts[:, 0], pts[:, 1], pts[:, 2], lat0, lon0, h0), axis=-1)
    np.testing.assert_allclose(ned, ref, atol=1e-6)
    np.testing.assert_allclose(fr.ned_to_ecef(ned, lat0, lon0, h0, deg=True), pts, atol=1e-6)


def test_radii_of_curvature_equator_and_pole():
    """Oracle: closed forms R_N(0) = a(1-e2), R_E(0) = a; R_N(90) = R_E(90) = a/sqrt(1-e2)."""
    from navcore.units import WGS84_A, WGS84_E2

    RN, RE = fr.radii_of_curvature(np.array([0.0, np.pi / 2]))
    np.testing.assert_allclose(RN, [WGS84_A * (1 - WGS84_E2), WGS84_A / np.sqrt(1 - WGS84_E2)])
    np.testing.assert_allclose(RE, [WGS84_A, WGS84_A / np.sqrt(1 - WGS84_E2)])


def test_bad_inputs_raise():
    with pytest.raises(ValueError, match=r"v must have shape \(\.\.\., 3\)"):
        fr.skew([1.0, 2.0])
    with pytest.raises(ValueError, match="lat must be a latitude"):
        fr.geodetic_to_ecef(100.0, 0.0, 0.0, deg=True)
    with pytest.raises(ValueError, match="q must be non-zero"):
        fr.quat_normalize([0.0, 0, 0, 0])
    with pytest.raises(ValueError, match="finite"):
        fr.dcm_from_euler(float("nan"), 0.0, 0.0)


def test_quaternion_helpers_batched_against_scipy():
    """Oracle: scipy Rotation (scalar-last quaternions) for batches of seeded random
    rotations, tiny rotations (1e-13 rad, the small-angle branch) and quaternions with a
    negative scalar part: rotation vector, rotated vectors and Euler angles."""
    rng = np.random.default_rng(12)
    rv = np.vstack([rng.normal(size=(20, 3)), 1e-13 * rng.normal(size=(5, 3)), [[0.0, 0.0, 0.0]]])
    R = Rotation.from_rotvec(rv)
    q = np.roll(R.as_quat(), 1, axis=-1)  # scalar first
    q[::2] *= -1.0  # the same rotations, negative scalar part
    np.testing.assert_allclose(fr.rotvec_from_quat(q), rv, rtol=1e-10, atol=1e-22)
    v = rng.normal(size=(26, 3))
    np.testing.assert_allclose(fr.quat_rotate(q, v), R.apply(v), atol=1e-12)
    for qi, Ri in zip(q[:20], R[:20], strict=True):
        yaw, pitch, roll = Ri.as_euler("ZYX")
        np.testing.assert_allclose(fr.euler_from_quat(qi), (roll, pitch, yaw), atol=1e-10)


def test_ecef_to_geodetic_default_is_radians():
    """Oracle: pymap3d with deg=False; the keyword default is radians, as for geodetic_to_ecef."""
    r = fr.geodetic_to_ecef(0.7, -1.2, 350.0)
    lat, lon, h = fr.ecef_to_geodetic(r)
    exp = pymap3d.ecef2geodetic(*r, deg=False)
    np.testing.assert_allclose([lat, lon, h], exp, rtol=0, atol=1e-9)


@pytest.mark.parametrize("axis", [0, 1, 2])
@pytest.mark.parametrize("angle", [np.pi, np.pi - 1e-3, 2.5])
def test_quat_from_dcm_half_turns_against_scipy(axis, angle):
    """Oracle: scipy Rotation, for rotations near a half turn about each axis, where the trace
    is about -1 and each of Shepperd's four branches is needed (w = 0 divides by zero in the
    trace branch); quaternions agree up to sign."""
    rv = np.zeros(3)
    rv[axis] = angle
    rv += 0.05 * np.eye(3)[(axis + 1) % 3] * (angle != np.pi)
    R = Rotation.from_rotvec(rv)
    q = fr.quat_from_dcm(R.as_matrix())
    expected = np.roll(R.as_quat(), 1)
    assert abs(float(q @ expected)) == pytest.approx(1.0, abs=1e-12)


def test_poles_and_radian_defaults_against_pymap3d():
    """Oracle: pymap3d (deg=False): a point on the polar axis (p = 0, the division guard of
    the closed form) has latitude +-90 deg; the NED helpers take radians by default."""
    for z in (6_356_752.314245 + 100.0, -6_356_752.314245 - 100.0):
        lat, _, h = fr.ecef_to_geodetic(np.array([0.0, 0.0, z]))
        assert float(lat) == pytest.approx(np.sign(z) * np.pi / 2, abs=1e-12)
        assert float(h) == pytest.approx(100.0, abs=1e-6)
    lat0, lon0, h0 = 0.6, 0.4, 120.0
    r = fr.geodetic_to_ecef(0.6001, 0.4002, 300.0)
    n = fr.ecef_to_ned(r, lat0, lon0, h0)
    np.testing.assert_allclose(n, pymap3d.ecef2ned(*r, lat0, lon0, h0, deg=False), atol=1e-6)
    np.testing.assert_allclose(fr.ned_to_ecef(n, lat0, lon0, h0), r, atol=1e-6)
    C = fr.dcm_ecef_to_ned(lat0, lon0)
    np.testing.assert_allclose(C @ (r - fr.geodetic_to_ecef(lat0, lon0, h0)), n, atol=1e-6)


def test_ecef_to_geodetic_down_to_the_documented_limit():
    """Oracles: closed forms on the equatorial plane (latitude 0, longitude atan2(y, x),
    height |r| - a) and on the polar axis (latitude +-90 deg, height |z| - b), at exactly
    100 km from the centre and just beyond it; the documentation rejects points closer than
    100 km (also one inside a batch) and arrays that do not end in an axis of 3."""
    from navcore.units import WGS84_A, WGS84_B

    for rho in (1e5, 1e5 + 0.5):
        r = np.array([0.6 * rho, 0.8 * rho, 0.0])
        lat, lon, h = fr.ecef_to_geodetic(r)
        assert (float(lat), float(lon)) == pytest.approx((0.0, np.arctan2(0.8, 0.6)), abs=1e-12)
        assert float(h) == pytest.approx(rho - WGS84_A, abs=1e-6)
        lat, _, h = fr.ecef_to_geodetic(np.array([0.0, 0.0, -rho]))
        assert float(lat) == pytest.approx(-np.pi / 2, abs=1e-12)
        assert float(h) == pytest.approx(rho - WGS84_B, abs=1e-6)
    surface = fr.geodetic_to_ecef(0.3, 0.2, 0.0)
    with pytest.raises(ValueError, match="100 km"):
        fr.ecef_to_geodetic(np.stack([surface, [0.0, 5e4, 0.0]]))
    with pytest.raises(ValueError, match="r_e"):
        fr.ecef_to_geodetic(np.array([6.4e6, 1.0]))


@pytest.mark.parametrize("angle", [0.9, 0.3, 1e-3])
def test_quat_from_rotvec_below_one_radian_against_scipy(angle):
    """Oracle: scipy Rotation.from_rotvec for rotation angles under 1 rad (the exact
    sin(a/2)/a branch; the series branch is for a < 1e-8 only), about an oblique axis."""
    axis = np.array([0.48, -0.6, 0.64])
    rv = angle * axis
    expected = np.roll(Rotation.from_rotvec(rv).as_quat(), 1)
    np.testing.assert_allclose(fr.quat_from_rotvec(rv), expected, rtol=0, atol=1e-15)


def test_quat_from_rotvec_series_branch_to_the_last_digits():
    """Oracle: scipy Rotation.from_rotvec at 9e-9 rad (the small-angle series branch of
    navcore): the vector part sin(a/2)/a r equals r/2 to the rounding of doubles (a^2/48 is
    below it), compared at 1e-15 relative."""
    rv = 9e-9 * np.array([0.48, -0.6, 0.64])
    expected = np.roll(Rotation.from_rotvec(rv).as_quat(), 1)
    q = fr.quat_from_rotvec(rv)
    np.testing.assert_allclose(q[1:], expected[1:], rtol=1e-15, atol=0)
    assert q[0] == expected[0] == 1.0
