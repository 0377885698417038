"""Edges of navcore.frames that the round-trip and bulk tests do not reach.

Found by the mutation run of the frames package (issue 31): the ellipsoid's flattening check,
the radian default of every ``deg`` keyword, the degree path of the elementary rotations and of
the Euler angles, the parameter names in shape errors, the quaternion conjugate, the
normalisation of nearly-unit quaternions, arcsin's clip at a pitch of +-90 deg reached by
rounding, and Python floats for one attitude.

Oracles: numpy's own unit conversion (np.radians/np.degrees) for the ``deg`` paths, the
quaternion conjugate's definition (scalar kept, vector negated), scipy's Rotation for the
Euler angles at gimbal lock, and exact arithmetic for the ellipsoid's interval.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import navcore.frames as fr

# --- the ellipsoid's flattening lies in [0, 1) -----------------------------------------------


@pytest.mark.parametrize("f", [0.0, 1.0 / 298.257223563, 0.999])
def test_ellipsoid_accepts_flattening_in_zero_one(f: float) -> None:
    """Oracle: the interval [0, 1) itself; 0 is a sphere, b = a."""
    ell = fr.Ellipsoid("test", 6.4e6, f)
    assert ell.b == pytest.approx(6.4e6 * (1.0 - f), rel=1e-15)


@pytest.mark.parametrize("f", [-1e-12, 1.0, 1.5])
def test_ellipsoid_rejects_flattening_outside_zero_one(f: float) -> None:
    with pytest.raises(ValueError, match=r"^Ellipsoid\.f must lie in \[0, 1\), got "):
        fr.Ellipsoid("test", 6.4e6, f)


# --- deg=False is the default: radians in, radians out ---------------------------------------

LAT0, LON0, H0 = 0.7, -1.2, 150.0  # rad, rad, m
AZ, EL, RANGE = 2.1, 0.4, 25_000.0


def _deg(*angles: float) -> list[float]:
    return [float(np.degrees(a)) for a in angles]


def test_aer_functions_default_to_radians() -> None:
    """Oracle: the same call in degrees with deg=True, converted by np.degrees/np.radians."""
    lat0d, lon0d = _deg(LAT0, LON0)
    azd, eld = _deg(AZ, EL)
    np.testing.assert_allclose(
        fr.aer_to_enu(AZ, EL, RANGE), fr.aer_to_enu(azd, eld, RANGE, deg=True), atol=1e-9
    )
    np.testing.assert_allclose(
        fr.aer_to_ned(AZ, EL, RANGE), fr.aer_to_ned(azd, eld, RANGE, deg=True), atol=1e-9
    )
    r = fr.aer_to_ecef(AZ, EL, RANGE, LAT0, LON0, H0)
    np.testing.assert_allclose(r, fr.aer_to_ecef(azd, eld, RANGE, lat0d, lon0d, H0, deg=True), atol=1e-6)
    lat, lon, h = fr.aer_to_geodetic(AZ, EL, RANGE, LAT0, LON0, H0)
    latd, lond, hd = fr.aer_to_geodetic(azd, eld, RANGE, lat0d, lon0d, H0, deg=True)
    np.testing.assert_allclose([np.degrees(lat), np.degrees(lon), h], [latd, lond, hd], atol=1e-6)
    for got, want in zip(fr.ecef_to_aer(r, LAT0, LON0, H0), (AZ, EL, RANGE), strict=True):
        assert got == pytest.approx(want, rel=1e-9)
    enu = fr.aer_to_enu(AZ, EL, RANGE)
    for got, want in zip(fr.enu_to_aer(enu), (AZ, EL, RANGE), strict=True):
        assert got == pytest.approx(want, rel=1e-12)
    ned = fr.aer_to_ned(AZ, EL, RANGE)
    for got, want in zip(fr.ned_to_aer(ned), (AZ, EL, RANGE), strict=True):
        assert got == pytest.approx(want, rel=1e-12)


def test_local_frame_functions_default_to_radians() -> None:
    """Oracle: the same call in degrees with deg=True."""
    lat0d, lon0d = _deg(LAT0, LON0)
    lat, lon, h = LAT0 + 1e-3, LON0 - 2e-3, 900.0
    latd, lond = _deg(lat, lon)
    enu = fr.geodetic_to_enu(lat, lon, h, LAT0, LON0, H0)
    np.testing.assert_allclose(enu, fr.geodetic_to_enu(latd, lond, h, lat0d, lon0d, H0, deg=True), atol=1e-6)
    ned = fr.geodetic_to_ned(lat, lon, h, LAT0, LON0, H0)
    np.testing.assert_allclose(ned, fr.geodetic_to_ned(latd, lond, h, lat0d, lon0d, H0, deg=True), atol=1e-6)
    np.testing.assert_allclose(
        fr.enu_to_ecef(enu, LAT0, LON0, H0), fr.enu_to_ecef(enu, lat0d, lon0d, H0, deg=True), atol=1e-6
    )
    back = fr.enu_to_geodetic(enu, LAT0, LON0, H0)
    np.testing.assert_allclose(back, (lat, lon, h), rtol=1e-9)
    back = fr.ned_to_geodetic(ned, LAT0, LON0, H0)
    np.testing.assert_allclose(back, (lat, lon, h), rtol=1e-9)
    az, el, srange = fr.geodetic_to_aer(lat, lon, h, LAT0, LON0, H0)
    azd, eld, srd = fr.geodetic_to_aer(latd, lond, h, lat0d, lon0d, H0, deg=True)
    np.testing.assert_allclose([np.degrees(az), np.degrees(el), srange], [azd, eld, srd], rtol=1e-9)


# --- deg=True reaches the elementary rotations and the Euler angles ----------------------------


@pytest.mark.parametrize("rot", [fr.rot_x, fr.rot_y, fr.rot_z])
def test_elementary_rotations_in_degrees(rot) -> None:
    """Oracle: np.radians of the angle, passed in radians."""
    np.testing.assert_allclose(rot(35.0, deg=True), rot(np.radians(35.0)), atol=1e-15)


def test_ecef_to_local_rotations_in_degrees() -> None:
    """Oracle: np.radians of the latitude and longitude, passed in radians."""
    for dcm in (fr.dcm_ecef_to_ned, fr.dcm_ecef_to_enu):
        np.testing.assert_allclose(
            dcm(40.0, -75.0, deg=True), dcm(np.radians(40.0), np.radians(-75.0)), atol=1e-15
        )


def test_euler_angles_in_degrees() -> None:
    """Oracle: np.degrees of the radian angles; scipy's intrinsic ZYX for the round trip."""
    C = Rotation.from_euler("ZYX", [30.0, -20.0, 10.0], degrees=True).as_matrix()
    np.testing.assert_allclose(fr.euler_from_dcm(C, deg=True), (10.0, -20.0, 30.0), atol=1e-12)
    q = fr.quat_from_euler(10.0, -20.0, 30.0, deg=True)
    np.testing.assert_allclose(fr.euler_from_quat(q, deg=True), (10.0, -20.0, 30.0), atol=1e-12)


def test_one_attitude_gives_python_floats() -> None:
    angles = fr.euler_from_dcm(np.eye(3))
    assert all(type(a) is float for a in angles)
    angles = fr.euler_from_quat([1.0, 0.0, 0.0, 0.0])
    assert all(type(a) is float for a in angles)
    stacked = fr.euler_from_dcm(np.stack([np.eye(3)] * 2))
    assert all(isinstance(a, np.ndarray) and a.shape == (2,) for a in stacked)


# --- shape errors name the parameter as the caller spelled it -----------------------------------

UNIT = [1.0, 0.0, 0.0, 0.0]


@pytest.mark.parametrize(
    ("call", "name", "size"),
    [
        (lambda: fr.quat_multiply([1.0, 0.0, 0.0], UNIT), "q", 4),
        (lambda: fr.quat_multiply(UNIT, [1.0, 0.0, 0.0]), "p", 4),
        (lambda: fr.quat_normalize([1.0, 2.0, 3.0]), "q", 4),
        (lambda: fr.quat_conjugate([1.0, 2.0, 3.0]), "q", 4),
        (lambda: fr.enu_to_aer([1.0, 2.0]), "r_enu", 3),
        (lambda: fr.ned_to_aer([1.0, 2.0]), "r_n", 3),
    ],
)
def test_shape_errors_name_the_parameter(call, name: str, size: int) -> None:
    with pytest.raises(ValueError, match=rf"^{name} must have shape \(\.\.\., {size}\), got "):
        call()


def test_quat_conjugate_negates_the_vector_part() -> None:
    """Oracle: the definition q* = [w, -x, -y, -z], one and stacked, any norm."""
    np.testing.assert_array_equal(fr.quat_conjugate([1.0, 2.0, -3.0, 4.0]), [1.0, -2.0, 3.0, -4.0])
    q = np.arange(12.0).reshape(3, 4)
    np.testing.assert_array_equal(fr.quat_conjugate(q), q * [1.0, -1.0, -1.0, -1.0])


# --- a nearly-unit quaternion is normalised before use -----------------------------------------


def test_nearly_unit_quaternions_are_normalised() -> None:
    """A quaternion within the unit tolerance (1e-6) gives the attitude of its normalised self.

    Oracle: the same functions on q / |q| (unscaled by a factor (1 + 5e-7)^2 they would be off
    by about 1e-6).
    """
    q = fr.quat_from_euler(0.1, 0.2, 0.3)
    scaled = q * (1.0 + 5e-7)
    np.testing.assert_allclose(fr.dcm_from_quat(scaled), fr.dcm_from_quat(q), atol=1e-14)
    np.testing.assert_allclose(fr.euler_from_quat(scaled), fr.euler_from_quat(q), atol=1e-14)
    np.testing.assert_allclose(fr.rotvec_from_quat(scaled), fr.rotvec_from_quat(q), atol=1e-14)
    batch = np.stack([q, fr.quat_from_euler(-0.4, 0.1, 2.0)]) * np.array([[1.0 + 5e-7], [1.0 - 5e-7]])
    np.testing.assert_allclose(
        fr.rotvec_from_quat(batch),
        fr.rotvec_from_quat(batch / np.linalg.norm(batch, axis=-1, keepdims=True)),
        atol=1e-14,
    )


# --- pitch of +-90 deg reached by rounding ------------------------------------------------------


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_euler_from_dcm_at_gimbal_lock_past_one_by_rounding(sign: float) -> None:
    """C[2, 0] one ulp beyond +-1 (rounding) still gives pitch -+90 deg, not NaN.

    Oracle: scipy's Rotation of the exact matrix gives pitch -+90 deg.
    """
    C = fr.dcm_from_euler(0.3, -sign * np.pi / 2, 0.2)
    with pytest.warns(UserWarning, match="Gimbal lock"):
        assert Rotation.from_matrix(C).as_euler("ZYX")[1] == pytest.approx(-sign * np.pi / 2, abs=1e-7)
    C[2, 0] = sign * np.nextafter(1.0, 2.0)
    assert fr.euler_from_dcm(C)[1] == -sign * np.pi / 2


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_euler_from_quat_at_gimbal_lock_past_one_by_rounding(sign: float) -> None:
    """A unit quaternion whose 2 (x z - w y) rounds one ulp past +-1 gives pitch +-90 deg."""
    q = np.array(
        [0.7071067813016019, 8.090474470513854e-10, sign * 0.7071067810714933, 5.471638848909756e-10]
    )
    w, x, y, z = q / np.linalg.norm(q)
    assert abs(2.0 * (x * z - w * y)) > 1.0  # the precondition: rounding past one
    assert fr.euler_from_quat(q)[1] == pytest.approx(sign * np.pi / 2, abs=1e-7)


# --- azimuth, elevation and range of stacks with two leading axes ---------------------------------


def test_aer_to_enu_on_a_two_axis_stack() -> None:
    """Oracle: the element-wise formula e = r cos(el) sin(az), n = r cos(el) cos(az), u = r sin(el)."""
    az = np.linspace(0.1, 6.0, 6).reshape(2, 3)
    el = np.linspace(-1.0, 1.2, 6).reshape(2, 3)
    r = np.linspace(1.0, 6.0, 6).reshape(2, 3)
    want = np.stack([r * np.cos(el) * np.sin(az), r * np.cos(el) * np.cos(az), r * np.sin(el)], -1)
    np.testing.assert_allclose(fr.aer_to_enu(az, el, r), want, atol=1e-14)
