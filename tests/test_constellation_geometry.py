"""GPS constellation, line-of-sight geometry and measurement models against independent oracles.

Oracles: circular Keplerian orbits built here from rotation matrices (scipy.spatial.transform)
and the WGS-84 constants, their analytic velocities, pymap3d's ECEF -> azimuth/elevation,
and finite differences of ranges along straight-line motion.
"""

from __future__ import annotations

import math

import numpy as np
import pymap3d
import pytest
from scipy.spatial.transform import Rotation

from navcore.gnss import constellation as cs
from navcore.gnss.measurements import pseudorange, pseudorange_rate

MU = 3.986004418e14  # WGS-84 GM, m^3/s^2
OMEGA_E = 7.292115e-5  # WGS-84 Earth rate, rad/s
A_GPS = 26_559_700.0  # IS-GPS-200 nominal semi-major axis, m


def _orbit(raan: float, u0: float, t: float, inc: float = math.radians(55.0), a: float = A_GPS):
    """ECEF position and velocity of a circular orbit: r_i = R3(raan) R1(inc) a [cos u, sin u, 0],
    u = u0 + n t with n = sqrt(mu/a^3); ECEF = R3(-omega_e t) r_i; v_e = R3(-omega_e t) v_i - w x r_e."""
    n = math.sqrt(MU / a**3)
    u = u0 + n * t
    rot = Rotation.from_euler("ZX", [raan, inc])
    r_i = rot.apply(a * np.array([math.cos(u), math.sin(u), 0.0]))
    v_i = rot.apply(a * n * np.array([-math.sin(u), math.cos(u), 0.0]))
    earth = Rotation.from_euler("Z", -OMEGA_E * t)
    r_e = earth.apply(r_i)
    v_e = earth.apply(v_i) - np.cross([0.0, 0.0, OMEGA_E], r_e)
    return r_e, v_e


def test_nominal_constellation_is_the_stated_walker_pattern() -> None:
    """Oracle: the stated 24/6/1-like pattern built by hand (planes 60 deg apart in node, slots
    90 deg apart, 15 deg between planes) as Keplerian circular orbits, at t = 0 and 5000 s."""
    c = cs.nominal_gps_constellation()
    assert c.prn.tolist() == list(range(1, 25))
    assert c.radius == A_GPS and c.inclination == pytest.approx(math.radians(55.0), abs=1e-15)
    assert 2 * math.pi / c.mean_motion == pytest.approx(43_082.0, abs=6.0)  # half a sidereal day, Kepler
    for t in (0.0, 5000.0):
        pos = c.positions_ecef(t)
        for k in range(24):
            plane, slot = divmod(k, 4)
            ref, _ = _orbit(math.radians(60.0 * plane), math.radians(90.0 * slot + 15.0 * plane), t)
            np.testing.assert_allclose(pos[k], ref, rtol=0, atol=1e-5)


def test_constellation_parameters_and_angle_ranges() -> None:
    """Oracle: a 3-plane, 5-slot pattern with a 7-deg offset and a 350-deg first node built by
    hand; the stored node and argument of latitude lie in [0, 2 pi) and equal the hand
    values modulo 2 pi; positions match at t = 0 and after 3 h."""
    c = cs.nominal_gps_constellation(n_planes=3, per_plane=5, phase_offset_deg=7.0, raan0_deg=350.0)
    assert c.prn.tolist() == list(range(1, 16))
    raan = np.radians(350.0 + 120.0 * np.repeat(np.arange(3), 5))
    arg = np.radians(72.0 * np.tile(np.arange(5), 3) + 7.0 * np.repeat(np.arange(3), 5))
    for got, ref in ((c.raan, raan), (c.arg_lat0, arg)):
        assert np.all((got >= 0) & (got < 2 * np.pi))
        np.testing.assert_allclose(got, np.mod(ref, 2 * np.pi), atol=1e-12)
    for t in (0.0, 10_800.0):
        pos = c.positions_ecef(t)
        for k in range(15):
            ref, _ = _orbit(raan[k], arg[k], t)
            np.testing.assert_allclose(pos[k], ref, rtol=0, atol=1e-5)


def test_positions_broadcast_over_times() -> None:
    """Oracle: the hand-built orbit at each time of a (2, 3) time array: shape (2, 3, N, 3)."""
    c = cs.nominal_gps_constellation(n_planes=2, per_plane=1, phase_offset_deg=30.0)
    t = np.array([[0.0, 100.0, 900.0], [4000.0, 2e4, 8e4]])
    pos = c.positions_ecef(t)
    assert pos.shape == (2, 3, 2, 3)
    ref, _ = _orbit(math.pi, math.radians(30.0), 2e4)
    np.testing.assert_allclose(pos[1, 1, 1], ref, rtol=0, atol=1e-5)


def test_velocities_match_the_analytic_orbit_velocity() -> None:
    """Oracle: the analytic ECEF velocity of a circular orbit, R3(-w t) v_i - w x r_e (about
    3.9 km/s inertial); the central difference of the model is accurate to ~3e-6 m/s, so a
    step three times longer (error ~3e-5 m/s) or a one-sided difference would fail."""
    c = cs.nominal_gps_constellation()
    for t in (0.0, 1234.5, np.array([10.0, 20_000.0])):
        v = c.velocities_ecef(t)
        tt = np.atleast_1d(t)
        v = v.reshape(tt.size, 24, 3)
        for i, ti in enumerate(tt):
            for k in range(24):
                plane, slot = divmod(k, 4)
                _, ref = _orbit(
                    math.radians(60.0 * plane), math.radians(90.0 * slot + 15.0 * plane), float(ti)
                )
                np.testing.assert_allclose(v[i, k], ref, rtol=0, atol=1e-5)


def test_line_of_sight_elevation_azimuth_and_visibility_against_pymap3d() -> None:
    """Oracle: pymap3d.ecef2aer (WGS-84) for elevation and azimuth of each satellite, the
    Euclidean distance for the range; the visibility mask is elevation >= mask."""
    c = cs.nominal_gps_constellation()
    lat, lon, h, t = 0.62, -1.9, 1500.0, 3700.0
    r_user = np.array(pymap3d.geodetic2ecef(math.degrees(lat), math.degrees(lon), h))
    sats = c.positions_ecef(t)
    u, rho = cs.line_of_sight(r_user, sats)
    el, az = cs.elevation_azimuth(r_user, sats, lat, lon)
    ref_az, ref_el, ref_rng = pymap3d.ecef2aer(
        sats[:, 0], sats[:, 1], sats[:, 2], math.degrees(lat), math.degrees(lon), h
    )
    np.testing.assert_allclose(rho, ref_rng, rtol=1e-12)
    np.testing.assert_allclose(u * rho[:, None], sats - r_user, rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose(np.degrees(el), ref_el, atol=1e-7)
    np.testing.assert_allclose(np.degrees(az), ref_az, atol=1e-7)
    assert np.all((az >= 0) & (az < 2 * np.pi))
    for mask in (5.0, 15.0, -3.0):
        np.testing.assert_array_equal(cs.visible(c, t, lat, lon, h, mask_deg=mask), ref_el >= mask)
    assert cs.visible(c, t, lat, lon, h).sum() == np.sum(ref_el >= 5.0)


def test_pseudorange_is_distance_plus_bias() -> None:
    """Oracle: math.dist plus the clock bias, per satellite."""
    rng = np.random.default_rng(2)
    r_user = rng.normal(0, 5e6, 3)
    sats = rng.normal(0, 2e7, (5, 3))
    got = pseudorange(r_user, sats, clock_bias_m=123.4)
    np.testing.assert_allclose(got, [math.dist(s, r_user) + 123.4 for s in sats], rtol=1e-14)
    assert pseudorange(r_user, sats[0]).shape == (1,)


def test_pseudorange_rate_is_the_time_derivative_of_the_pseudorange() -> None:
    """Oracle: central finite difference (h = 1e-3 s) of |r_s + v_s t - r_u - v_u t| + b + b' t
    along straight-line motion of user and satellites, for five satellites and a clock drift."""
    rng = np.random.default_rng(4)
    r_user, v_user = rng.normal(0, 5e6, 3), rng.normal(0, 300, 3)
    sats, v_sats = rng.normal(0, 2e7, (5, 3)), rng.normal(0, 3000, (5, 3))
    drift, h = 0.37, 1e-3

    def rho(t: float) -> np.ndarray:
        return np.linalg.norm(sats + v_sats * t - r_user - v_user * t, axis=1) + 10.0 + drift * t

    fd = (rho(h) - rho(-h)) / (2 * h)
    got = pseudorange_rate(r_user, v_user, sats, v_sats, clock_drift_mps=drift)
    np.testing.assert_allclose(got, fd, rtol=0, atol=1e-4)
    one = pseudorange_rate(r_user, v_user, sats[1], v_sats[1])
    np.testing.assert_allclose(one, fd[1] - drift, atol=1e-4)
    with pytest.raises(ValueError, match="r_sat"):
        pseudorange_rate(r_user, v_user, r_user, v_sats[0])


def test_velocity_step_and_stored_angles_for_other_arguments() -> None:
    """Oracle: the analytic orbit velocity with the central-difference step given explicitly
    (0.25 s), and a phase offset large enough (100 deg between planes) that the hand-built
    argument of latitude exceeds 2 pi and must be wrapped into [0, 2 pi)."""
    c = cs.nominal_gps_constellation()
    v = c.velocities_ecef(777.0, dt=0.25)
    _, ref = _orbit(math.radians(60.0), math.radians(90.0 * 3 + 15.0), 777.0)
    np.testing.assert_allclose(v[7], ref, rtol=0, atol=1e-5)
    c = cs.nominal_gps_constellation(n_planes=3, per_plane=4, phase_offset_deg=100.0)
    arg = np.radians(90.0 * np.tile(np.arange(4), 3) + 100.0 * np.repeat(np.arange(3), 4))
    assert arg.max() > 2 * np.pi
    np.testing.assert_allclose(c.arg_lat0, np.mod(arg, 2 * np.pi), atol=1e-12)


def test_geometry_of_stacked_epochs_and_single_satellites() -> None:
    """Oracle: per-epoch Euclidean distances for satellites stacked over epochs (T, N, 3) and
    for one satellite given as a (3,) vector, in line_of_sight and pseudorange."""
    c = cs.nominal_gps_constellation()
    r_user = np.array(pymap3d.geodetic2ecef(40.0, 10.0, 0.0))
    sats = c.positions_ecef(np.array([0.0, 600.0]))  # (2, 24, 3)
    u, rho = cs.line_of_sight(r_user, sats)
    assert rho.shape == (2, 24) and u.shape == (2, 24, 3)
    np.testing.assert_allclose(rho[1, 5], math.dist(sats[1, 5], r_user), rtol=1e-14)
    np.testing.assert_allclose(u[1, 5] * rho[1, 5], sats[1, 5] - r_user, atol=1e-6)
    u1, rho1 = cs.line_of_sight(r_user, sats[0, 3])
    assert float(rho1) == pytest.approx(math.dist(sats[0, 3], r_user), rel=1e-14)
    np.testing.assert_allclose(np.ravel(u1) * float(rho1), sats[0, 3] - r_user, atol=1e-6)
    pr = pseudorange(r_user, sats)
    np.testing.assert_allclose(pr[1, 5], math.dist(sats[1, 5], r_user), rtol=1e-14)
    assert pseudorange(r_user, sats[0, 3])[0] == pytest.approx(math.dist(sats[0, 3], r_user), rel=1e-14)


def test_pseudorange_rate_geometry_edge_cases() -> None:
    """Oracle: finite differences of the range as above when every satellite shares the user's
    x coordinate (a zero column of the offsets is not a zero range), and a satellite at the
    user's position among others is rejected (no line of sight)."""
    r_user, v_user = np.array([1.0e6, 2.0e6, 3.0e6]), np.array([10.0, -20.0, 5.0])
    sats = np.array([[1.0e6, 2.2e7, 1.0e7], [1.0e6, -1.5e7, 2.0e7], [1.0e6, 5.0e6, -2.1e7]])
    v_sats = np.array([[100.0, 2000.0, -300.0], [-50.0, 100.0, 2500.0], [0.0, -900.0, 40.0]])
    h = 1e-3

    def rho(t: float) -> np.ndarray:
        return np.linalg.norm(sats + v_sats * t - r_user - v_user * t, axis=1)

    np.testing.assert_allclose(
        pseudorange_rate(r_user, v_user, sats, v_sats), (rho(h) - rho(-h)) / (2 * h), atol=1e-4
    )
    with pytest.raises(ValueError, match="r_sat"):
        pseudorange_rate(r_user, v_user, np.vstack([sats, r_user]), np.vstack([v_sats, v_user]))


@pytest.mark.parametrize(
    ("lat", "lon", "sign", "elevation"),
    [
        (0.5118732440808911, 0.8831370694455005, 1.0, 90.0),
        (-0.5645056439685436, -0.4600413061645461, -1.0, -90.0),
    ],
)
def test_zenith_and_nadir_elevations_are_exact(lat, lon, sign, elevation) -> None:
    """Oracle: geometry: a satellite straight up (down) the local vertical is at +90 (-90) deg
    elevation. These positions (found by a seeded search) make the rounded sine of the
    elevation 1 + 2e-16 in magnitude, so it must be clipped."""
    r = np.array(pymap3d.geodetic2ecef(math.degrees(lat), math.degrees(lon), 0.0))
    up = np.array([math.cos(lat) * math.cos(lon), math.cos(lat) * math.sin(lon), math.sin(lat)])
    sat = r + sign * 3.0e6 * up
    el, _ = cs.elevation_azimuth(r, sat[None], lat, lon)
    assert math.degrees(float(el[0])) == pytest.approx(elevation, abs=1e-6)


def test_visibility_mask_default_and_boundary() -> None:
    """Oracle: pymap3d elevations; the default mask is 5 deg (a time and place is searched at
    which one satellite lies between 5 and 6 deg), and a satellite exactly at the mask counts."""
    c = cs.nominal_gps_constellation()
    lat, lon = 0.3, 2.0
    for t in np.arange(0.0, 43_200.0, 60.0):
        s = c.positions_ecef(t)
        _, el, _ = pymap3d.ecef2aer(s[:, 0], s[:, 1], s[:, 2], math.degrees(lat), math.degrees(lon), 0.0)
        if np.any((el >= 5.0) & (el < 6.0)):
            break
    else:
        pytest.fail("no satellite between 5 and 6 deg")
    np.testing.assert_array_equal(cs.visible(c, t, lat, lon, 0.0), el >= 5.0)
    # a satellite on the x axis seen from (0, 0, 0): exactly overhead (90 deg = the mask)
    overhead = cs.Constellation(np.zeros(1), np.zeros(1), 0.0, 2.6e7, np.array([1]))
    assert cs.visible(overhead, 0.0, 0.0, 0.0, 0.0, mask_deg=90.0).tolist() == [True]
