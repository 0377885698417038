"""Frames in bulk (issue 30, item 4): stacks of attitudes and positions, array origins,
ENU and AER beside NED, and the ellipsoid as an argument.

Oracles: pymap3d (geodetic, ECEF, ENU, NED, AER on random stacks, element by element, with
the same ellipsoid built from its axes) and scipy.spatial.transform.Rotation (attitude
conversions on random stacks). Both are independent of navcore's code.
"""

from __future__ import annotations

import numpy as np
import pymap3d
import pytest
from scipy.spatial.transform import Rotation

from navcore import frames as fr

N = 200
ELLIPSOIDS = {
    "WGS84": fr.WGS84,
    "GRS80": fr.GRS80,
    "sphere": fr.Ellipsoid("sphere", 6_371_000.0, 0.0),
}


def _pm_ellipsoid(ell: fr.Ellipsoid) -> pymap3d.Ellipsoid:
    return pymap3d.Ellipsoid(ell.a, ell.b, name=ell.name)


def _random_geodetic(rng: np.random.Generator, n: int = N) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    lat = rng.uniform(-89.9, 89.9, n)
    lon = rng.uniform(-180.0, 180.0, n)
    h = rng.uniform(-400.0, 30_000.0, n)
    return lat, lon, h


@pytest.mark.parametrize("name", ELLIPSOIDS)
def test_geodetic_ecef_round_trip_against_pymap3d(name):
    """Oracle: pymap3d.geodetic2ecef / ecef2geodetic with the same ellipsoid (a, b)."""
    ell, pm = ELLIPSOIDS[name], _pm_ellipsoid(ELLIPSOIDS[name])
    rng = np.random.default_rng(1)
    lat, lon, h = _random_geodetic(rng)
    r = fr.geodetic_to_ecef(lat, lon, h, deg=True, ellipsoid=ell)
    np.testing.assert_allclose(r, np.stack(pymap3d.geodetic2ecef(lat, lon, h, ell=pm), -1), atol=1e-6)
    lat2, lon2, h2 = fr.ecef_to_geodetic(r, deg=True, ellipsoid=ell)
    ref = pymap3d.ecef2geodetic(r[:, 0], r[:, 1], r[:, 2], ell=pm)
    np.testing.assert_allclose(lat2, ref[0], atol=1e-9)
    np.testing.assert_allclose(lon2, ref[1], atol=1e-9)
    np.testing.assert_allclose(h2, ref[2], atol=1e-5)
    np.testing.assert_allclose(lat2, lat, atol=1e-9)
    np.testing.assert_allclose(h2, h, atol=1e-5)


@pytest.mark.parametrize("name", ELLIPSOIDS)
def test_local_frames_with_array_origins_against_pymap3d(name):
    """Oracle: pymap3d ecef2enu, ecef2ned, enu2ecef, ned2ecef, geodetic2enu, geodetic2ned,
    enu2geodetic, ned2geodetic with one origin per point (arrays of origins)."""
    ell, pm = ELLIPSOIDS[name], _pm_ellipsoid(ELLIPSOIDS[name])
    rng = np.random.default_rng(2)
    lat0, lon0, h0 = _random_geodetic(rng)
    lat = lat0 + rng.uniform(-0.5, 0.5, N)
    lat = np.clip(lat, -89.9, 89.9)
    lon = lon0 + rng.uniform(-0.5, 0.5, N)
    h = h0 + rng.uniform(-1000.0, 1000.0, N)
    r = fr.geodetic_to_ecef(lat, lon, h, deg=True, ellipsoid=ell)
    x, y, z = r[:, 0], r[:, 1], r[:, 2]
    kw = {"deg": True, "ellipsoid": ell}
    enu = fr.ecef_to_enu(r, lat0, lon0, h0, **kw)
    ned = fr.ecef_to_ned(r, lat0, lon0, h0, **kw)
    np.testing.assert_allclose(
        enu, np.stack(pymap3d.ecef2enu(x, y, z, lat0, lon0, h0, ell=pm), -1), atol=1e-6
    )
    np.testing.assert_allclose(
        ned, np.stack(pymap3d.ecef2ned(x, y, z, lat0, lon0, h0, ell=pm), -1), atol=1e-6
    )
    np.testing.assert_allclose(fr.geodetic_to_enu(lat, lon, h, lat0, lon0, h0, **kw), enu, atol=1e-6)
    np.testing.assert_allclose(
        fr.geodetic_to_ned(lat, lon, h, lat0, lon0, h0, **kw),
        np.stack(pymap3d.geodetic2ned(lat, lon, h, lat0, lon0, h0, ell=pm), -1),
        atol=1e-6,
    )
    e, n, u = enu[:, 0], enu[:, 1], enu[:, 2]
    np.testing.assert_allclose(
        fr.enu_to_ecef(enu, lat0, lon0, h0, **kw),
        np.stack(pymap3d.enu2ecef(e, n, u, lat0, lon0, h0, ell=pm), -1),
        atol=1e-6,
    )
    np.testing.assert_allclose(fr.ned_to_ecef(ned, lat0, lon0, h0, **kw), r, atol=1e-6)
    back = fr.enu_to_geodetic(enu, lat0, lon0, h0, **kw)
    ref = pymap3d.enu2geodetic(e, n, u, lat0, lon0, h0, ell=pm)
    np.testing.assert_allclose(back[0], ref[0], atol=1e-9)
    np.testing.assert_allclose(back[1], ref[1], atol=1e-9)
    np.testing.assert_allclose(back[2], ref[2], atol=1e-5)
    back = fr.ned_to_geodetic(ned, lat0, lon0, h0, **kw)
    np.testing.assert_allclose(back[0], lat, atol=1e-9)
    np.testing.assert_allclose(back[2], h, atol=1e-5)


@pytest.mark.parametrize("name", ELLIPSOIDS)
def test_aer_against_pymap3d(name):
    """Oracle: pymap3d geodetic2aer, aer2geodetic, ecef2aer, aer2ecef, enu2aer, aer2enu
    (azimuth wrapped to [0, 360), elevation, slant range)."""
    ell, pm = ELLIPSOIDS[name], _pm_ellipsoid(ELLIPSOIDS[name])
    rng = np.random.default_rng(3)
    lat0, lon0, h0 = _random_geodetic(rng)
    lat = np.clip(lat0 + rng.uniform(-2.0, 2.0, N), -89.9, 89.9)
    lon = lon0 + rng.uniform(-2.0, 2.0, N)
    h = h0 + rng.uniform(100.0, 20_000.0, N)
    kw = {"deg": True, "ellipsoid": ell}
    az, el, rng_m = fr.geodetic_to_aer(lat, lon, h, lat0, lon0, h0, **kw)
    ref = pymap3d.geodetic2aer(lat, lon, h, lat0, lon0, h0, ell=pm)
    np.testing.assert_allclose(az, ref[0], atol=1e-8)
    np.testing.assert_allclose(el, ref[1], atol=1e-8)
    np.testing.assert_allclose(rng_m, ref[2], atol=1e-6)
    r = fr.geodetic_to_ecef(lat, lon, h, **kw)
    got = fr.ecef_to_aer(r, lat0, lon0, h0, **kw)
    ref = pymap3d.ecef2aer(r[:, 0], r[:, 1], r[:, 2], lat0, lon0, h0, ell=pm)
    for a, b in zip(got, ref, strict=True):
        np.testing.assert_allclose(a, b, atol=1e-6)
    np.testing.assert_allclose(
        fr.aer_to_ecef(az, el, rng_m, lat0, lon0, h0, **kw),
        np.stack(pymap3d.aer2ecef(az, el, rng_m, lat0, lon0, h0, ell=pm), -1),
        atol=1e-6,
    )
    back = fr.aer_to_geodetic(az, el, rng_m, lat0, lon0, h0, **kw)
    ref = pymap3d.aer2geodetic(az, el, rng_m, lat0, lon0, h0, ell=pm)
    np.testing.assert_allclose(back[0], ref[0], atol=1e-9)
    np.testing.assert_allclose(back[1], ref[1], atol=1e-9)
    np.testing.assert_allclose(back[2], ref[2], atol=1e-5)
    enu = fr.aer_to_enu(az, el, rng_m, deg=True)
    np.testing.assert_allclose(enu, np.stack(pymap3d.aer2enu(az, el, rng_m), -1), atol=1e-6)
    for a, b in zip(fr.enu_to_aer(enu, deg=True), pymap3d.enu2aer(*enu.T), strict=True):
        np.testing.assert_allclose(a, b, atol=1e-8)
    ned = fr.aer_to_ned(az, el, rng_m, deg=True)
    np.testing.assert_allclose(ned, enu[:, [1, 0, 2]] * [1, 1, -1], atol=1e-9)
    for a, b in zip(fr.ned_to_aer(ned, deg=True), (az, el, rng_m), strict=True):
        np.testing.assert_allclose(a, b, atol=1e-8)


def test_radians_default_and_broadcasting_grid_against_pymap3d():
    """Oracle: pymap3d with deg=False; a (M, K) grid of points against K origins broadcasts
    (one origin per column), and one origin against many points."""
    rng = np.random.default_rng(4)
    lat0 = np.radians(rng.uniform(-60, 60, 5))
    lon0 = np.radians(rng.uniform(-170, 170, 5))
    h0 = rng.uniform(0, 500, 5)
    pts = fr.geodetic_to_ecef(
        lat0 + np.radians(rng.uniform(-1, 1, (7, 5))), lon0 + np.radians(rng.uniform(-1, 1, (7, 5))), 1000.0
    )
    assert pts.shape == (7, 5, 3)
    enu = fr.ecef_to_enu(pts, lat0, lon0, h0)
    assert enu.shape == (7, 5, 3)
    for i in range(7):
        ref = np.stack(pymap3d.ecef2enu(*pts[i].T, lat0, lon0, h0, deg=False), -1)
        np.testing.assert_allclose(enu[i], ref, atol=1e-6)
    one = fr.ecef_to_enu(pts, float(lat0[0]), float(lon0[0]), float(h0[0]))
    ref = np.stack(pymap3d.ecef2enu(*pts.reshape(-1, 3).T, lat0[0], lon0[0], h0[0], deg=False), -1)
    np.testing.assert_allclose(one.reshape(-1, 3), ref, atol=1e-6)
    C = fr.dcm_ecef_to_ned(lat0, lon0)
    assert C.shape == (5, 3, 3)
    np.testing.assert_allclose(
        fr.dcm_ecef_to_enu(lat0, lon0), C[:, [1, 0, 2]] * np.array([1, 1, -1])[:, None]
    )
    R_N, _ = fr.radii_of_curvature(np.degrees(lat0), deg=True, ellipsoid=fr.GRS80)
    np.testing.assert_allclose(R_N, fr.radii_of_curvature(lat0, ellipsoid=fr.GRS80)[0])


# --- attitude -----------------------------------------------------------------------------
def _random_rotations(shape: tuple[int, ...], seed: int) -> Rotation:
    return Rotation.random(int(np.prod(shape)), random_state=seed)


@pytest.mark.parametrize("shape", [(50,), (4, 6), (2, 3, 5)])
def test_attitude_conversions_on_stacks_against_scipy(shape):
    """Oracle: scipy Rotation: matrix, scalar-last quaternion, intrinsic ZYX Euler angles
    (yaw, pitch, roll) and rotation vectors, for random stacks of any depth."""
    R = _random_rotations(shape, seed=len(shape))
    mats = R.as_matrix().reshape(*shape, 3, 3)
    quats = np.roll(R.as_quat(), 1, axis=-1).reshape(*shape, 4)
    quats = np.where(quats[..., :1] < 0, -quats, quats)
    yaw, pitch, roll = (a.reshape(shape) for a in R.as_euler("ZYX").T)
    np.testing.assert_allclose(fr.dcm_from_euler(roll, pitch, yaw), mats, atol=1e-12)
    np.testing.assert_allclose(
        fr.dcm_from_euler(np.degrees(roll), np.degrees(pitch), np.degrees(yaw), deg=True), mats, atol=1e-12
    )
    np.testing.assert_allclose(fr.quat_from_euler(roll, pitch, yaw), quats, atol=1e-12)
    np.testing.assert_allclose(fr.dcm_from_quat(quats), mats, atol=1e-12)
    np.testing.assert_allclose(fr.quat_from_dcm(mats), quats, atol=1e-12)
    for got, exp in zip(fr.euler_from_dcm(mats), (roll, pitch, yaw), strict=True):
        np.testing.assert_allclose(got, exp, atol=1e-10)
    for got, exp in zip(fr.euler_from_quat(quats, deg=True), (roll, pitch, yaw), strict=True):
        np.testing.assert_allclose(got, np.degrees(exp), atol=1e-8)
    np.testing.assert_allclose(fr.rotvec_from_quat(quats), R.as_rotvec().reshape(*shape, 3), atol=1e-10)
    np.testing.assert_allclose(fr.quat_from_rotvec(R.as_rotvec().reshape(*shape, 3)), quats, atol=1e-12)
    v = np.random.default_rng(7).normal(size=(*shape, 3))
    np.testing.assert_allclose(
        fr.quat_rotate(quats, v), R.apply(v.reshape(-1, 3)).reshape(*shape, 3), atol=1e-12
    )
    Q2 = _random_rotations(shape, seed=99)
    q2 = np.roll(Q2.as_quat(), 1, axis=-1).reshape(*shape, 4)
    prod = fr.quat_multiply(quats, q2)
    np.testing.assert_allclose(fr.dcm_from_quat(prod), (R * Q2).as_matrix().reshape(*shape, 3, 3), atol=1e-12)
    angles = np.random.default_rng(8).uniform(-3, 3, shape)
    for axis, rot in zip("xyz", (fr.rot_x, fr.rot_y, fr.rot_z), strict=True):
        exp = Rotation.from_euler(axis, angles.ravel()[:, None]).as_matrix().reshape(*shape, 3, 3)
        np.testing.assert_allclose(rot(angles), exp, atol=1e-12)
    np.testing.assert_allclose(np.matmul(fr.skew(v), v[..., None])[..., 0], 0.0, atol=1e-12)


def test_single_values_keep_their_shapes():
    """One attitude in, one out: matrices (3, 3), quaternions (4,), Euler angles floats."""
    C = fr.dcm_from_euler(0.1, 0.2, 0.3)
    assert C.shape == (3, 3)
    assert fr.quat_from_dcm(C).shape == (4,)
    roll, _, yaw = fr.euler_from_dcm(C)
    assert isinstance(roll, float) and isinstance(yaw, float)
    assert fr.geodetic_to_ecef(0.1, 0.2, 0.0).shape == (3,)
