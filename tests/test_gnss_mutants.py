"""Gaps in the navcore.gnss tests found by mutation testing (issue 31, 7 December 2026).

Each test names its oracle: closed forms derived by hand (the DOP of one satellite at the
zenith and three on the horizon, the Friis threshold range, Kaplan & Hegarty's jitter
formulas, the inclination of a circular orbit as the largest latitude of its ground track),
pymap3d's ``ecef2aer`` for elevations and azimuths, mpmath's quadrature of sinc^2 for the
spectral-separation factor, and the definition (G' W G)^-1 of the DOP covariance, computed
geometry by geometry with numpy.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pymap3d
import pytest

from navcore.frames import Ellipsoid, geodetic_to_ecef
from navcore.gnss.antijam import code_tracking_sigma_chips, spectral_separation_q
from navcore.gnss.constellation import elevation_azimuth, nominal_gps_constellation, visible
from navcore.gnss.dop import dilution_of_precision, dop_from_lines_of_sight
from navcore.gnss.jammer_geometry import (
    dll_thermal_jitter_chips,
    hysteresis_from_conditions,
    pll_thermal_jitter_deg,
    threshold_range_m,
)
from navcore.gnss.measurements import pseudorange, pseudorange_rate


def _los(el_deg, az_deg) -> np.ndarray:
    el, az = np.radians(el_deg), np.radians(az_deg)
    return np.c_[np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), -np.sin(el)]


def _own_covariance(u_ned: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Oracle: (G' W G)^-1 with rows [-u', 1] (range grows as the receiver moves away)."""
    G = np.column_stack([-u_ned, np.ones(len(u_ned))])
    return np.linalg.inv(G.T @ np.diag(w) @ G)


# --- dop -----------------------------------------------------------------------------------


def test_covariance_of_zenith_and_horizon_geometry_is_the_closed_form():
    """Oracle: closed form. Zenith satellite and three on the horizon 120 deg apart:
    G'G = diag(3/2, 3/2, [[1, 1], [1, 4]]) in (north, east, (down, clock)), whose inverse has
    the down/clock block [[4, -1], [-1, 1]] / 3: a receiver placed too low reads every range
    to the zenith satellite long, like a late clock, so the two errors are anticorrelated."""
    u = np.vstack([[0.0, 0.0, -1.0], _los(np.zeros(3), [0.0, 120.0, 240.0])])
    expected = np.zeros((4, 4))
    expected[0, 0] = expected[1, 1] = 2.0 / 3.0
    expected[2:, 2:] = np.array([[4.0, -1.0], [-1.0, 1.0]]) / 3.0
    np.testing.assert_allclose(dop_from_lines_of_sight(u).covariance, expected, atol=1e-14)


def test_a_stack_of_geometries_gives_each_its_own_dop():
    """Oracle: the definition (G' W G)^-1, one geometry at a time."""
    rng = np.random.default_rng(3)
    u = np.stack([_los(rng.uniform(10, 80, 5), rng.uniform(0, 360, 5)) for _ in range(2)])
    w = np.array([[1.0, 1.0, 1.0, 1.0, 1.0], [1.0, 0.0, 2.0, 0.5, 1.0]])
    d = dop_from_lines_of_sight(u, weights=w)
    assert d.n_used.tolist() == [5, 4]
    for i in range(2):
        D = _own_covariance(u[i], w[i])
        np.testing.assert_allclose(d.covariance[i], D, rtol=1e-10)
        assert d.hdop[i] == pytest.approx(math.sqrt(D[0, 0] + D[1, 1]), rel=1e-10)
        assert d.vdop[i] == pytest.approx(math.sqrt(D[2, 2]), rel=1e-10)
        assert d.gdop[i] == pytest.approx(math.sqrt(np.trace(D)), rel=1e-10)
    # a covariance is returned exactly symmetric, as a consumer's Cholesky expects
    assert np.array_equal(d.covariance, np.swapaxes(d.covariance, -1, -2))
    one = dop_from_lines_of_sight(u[1], weights=w[1]).covariance
    assert np.array_equal(one, one.T)


def test_one_geometry_gives_plain_numbers():
    """Oracle: the type contract (a scalar, not a 0-d array, for one geometry)."""
    d = dop_from_lines_of_sight(np.vstack([[0.0, 0.0, -1.0], _los(np.zeros(3), [0.0, 120.0, 240.0])]))
    for value in (d.gdop, d.pdop, d.hdop, d.vdop, d.tdop, d.n_used):
        assert not isinstance(value, np.ndarray)
    assert int(d.n_used) == 4


def test_solvability_follows_the_condition_number_and_not_the_weights_scale():
    """Oracle: the condition number of G'G from numpy's eigenvalues; a geometry with four
    satellites on a cone (a rank-deficient G'G) tilted by ``delta`` deg becomes solvable when
    the condition number falls below 1e12, and scaling every weight by 1e-3 changes neither
    the solvability nor anything but a factor 1e3 of the covariance (sqrt(1e3) of the GDOP)."""
    for delta, solvable in ((2.3e-4, False), (4.7e-4, True), (1e-3, True)):
        u = _los([30.0, 30.0, 30.0, 30.0 + delta], [0.0, 90.0, 180.0, 270.0])
        G = np.column_stack([-u, np.ones(4)])
        eig = np.linalg.eigvalsh(G.T @ G)
        assert bool(eig[-1] / eig[0] < 1e12) == solvable  # the case is on the intended side
        assert eig[-2] < 0.5 * eig[-1]
        assert bool(np.isfinite(dop_from_lines_of_sight(u).gdop)) == solvable
        small = dop_from_lines_of_sight(u, weights=np.full(4, 1e-3))
        assert bool(np.isfinite(small.gdop)) == solvable
        if solvable:
            assert small.gdop == pytest.approx(math.sqrt(1e3) * dop_from_lines_of_sight(u).gdop, rel=1e-4)


def test_lines_of_sight_are_checked():
    """Oracle: the documented contract (unit rows ending in 3 components)."""
    with pytest.raises(ValueError, match="u_ned must have shape"):
        dop_from_lines_of_sight([0.0, 0.0, -1.0])
    u = np.vstack([[0.0, 0.0, -1.0], _los(np.zeros(3), [0.0, 120.0, 240.0])])
    with pytest.raises(ValueError, match="unit lines of sight"):
        dop_from_lines_of_sight(1.001 * u)


def _sky(r: np.ndarray) -> np.ndarray:
    """Four satellites well spread over the sky of receiver ``r`` (ECEF, m)."""
    lat, lon, _ = pymap3d.ecef2geodetic(*r, deg=True)
    return np.array(
        [
            pymap3d.aer2ecef(az, el, 2.0e7, lat, lon, 0.0)
            for az, el in ((0, 60), (90, 40), (200, 50), (300, 30))
        ]
    )


def test_ecef_inputs_are_checked():
    """Oracle: the documented contract (shapes, a receiver off the Earth's centre, no
    satellite at the receiver)."""
    r = geodetic_to_ecef(45.0, 10.0, 0.0, deg=True)
    sats = _sky(r)
    with pytest.raises(ValueError, match="r_receiver must have shape"):
        dilution_of_precision(1.0, sats)
    with pytest.raises(ValueError, match="r_sat must have shape"):
        dilution_of_precision(r, sats[0])
    with pytest.raises(ValueError, match="coincide"):
        dilution_of_precision(r, np.vstack([sats, r]))
    with pytest.raises(ValueError, match=r"^r_receiver must be at least 100 km"):
        dilution_of_precision([10.0, 0.0, 0.0], sats)
    with pytest.raises(
        ValueError, match=r"^r_receiver must be at least 100 km"
    ):  # one of a stack of receivers
        dilution_of_precision(np.stack([r, [10.0, 0.0, 0.0]]), np.stack([sats, sats]))
    # exactly 100 km from the centre is accepted ("at least 100 km")
    d = dilution_of_precision(
        [1.0e5, 0.0, 0.0], [[3e7, 0, 0], [1e5, 2e7, 0], [1e5, -2e7, 0], [1e5, 0, 2e7], [1e5, 0, -2e7]]
    )
    assert int(d.n_used) == 5 and np.isfinite(d.gdop)


def test_default_mask_uses_every_satellite_above_the_horizon():
    """Oracle: pymap3d places a satellite at 3 deg elevation; the default mask is 0."""
    r = geodetic_to_ecef(45.0, 10.0, 0.0, deg=True)
    low = pymap3d.aer2ecef(120.0, 3.0, 2.0e7, 45.0, 10.0, 0.0)
    assert int(dilution_of_precision(r, np.vstack([_sky(r), low])).n_used) == 5


def test_a_satellite_exactly_at_the_mask_is_used():
    """Oracle: closed form. On the equator at longitude 0 the local down is -x, so a satellite
    displaced along y is at elevation exactly 0, the mask."""
    r = np.array([6378137.0, 0.0, 0.0])
    sats = np.array(
        [[6378137.0, 2e7, 0.0], [2.6e7, 0.0, 0.0], [2e7, 1e7, 1e7], [2e7, -1e7, 1e7], [2e7, 0.0, -1e7]]
    )
    assert int(dilution_of_precision(r, sats, mask=0.0).n_used) == 5


def test_zenith_and_nadir_satellites_survive_rounding():
    """Oracle: closed form (a satellite on the local vertical is at elevation +-90 deg). Over
    200 seeded receivers some lines of sight come out with a down component just beyond 1
    in magnitude; the zenith satellite is still used, and with a mask of -90 deg so is one at
    the nadir."""
    rng = np.random.default_rng(7)
    lat, lon = rng.uniform(-80.0, 80.0, 200), rng.uniform(-180.0, 180.0, 200)
    r = geodetic_to_ecef(lat, lon, np.zeros(200), deg=True)
    up = np.c_[
        np.cos(np.radians(lat)) * np.cos(np.radians(lon)),
        np.cos(np.radians(lat)) * np.sin(np.radians(lon)),
        np.sin(np.radians(lat)),
    ]
    sats = np.stack([np.vstack([r[i] + 2e7 * up[i], _sky(r[i])]) for i in range(200)])
    assert np.all(dilution_of_precision(r, sats).n_used == 5)
    nadir = np.stack([np.vstack([r[i] - 2e6 * up[i], _sky(r[i])]) for i in range(200)])
    assert np.all(dilution_of_precision(r, nadir, mask=-90.0, deg=True).n_used == 5)


def test_the_local_vertical_comes_from_the_given_ellipsoid():
    """Oracle: on a sphere the local vertical is the geocentric radius; the lines of sight
    resolved in that frame and the definition (G'G)^-1 give the VDOP."""
    sphere = Ellipsoid("sphere", 6_371_000.0, 0.0)
    lat, lon = math.radians(45.0), math.radians(10.0)
    r = 6_371_000.0 * np.array([math.cos(lat) * math.cos(lon), math.cos(lat) * math.sin(lon), math.sin(lat)])
    sats = _sky(r)
    C = np.array(
        [
            [-math.sin(lat) * math.cos(lon), -math.sin(lat) * math.sin(lon), math.cos(lat)],
            [-math.sin(lon), math.cos(lon), 0.0],
            [-math.cos(lat) * math.cos(lon), -math.cos(lat) * math.sin(lon), -math.sin(lat)],
        ]
    )
    u = (sats - r) / np.linalg.norm(sats - r, axis=1, keepdims=True) @ C.T
    D = _own_covariance(u, np.ones(4))
    d = dilution_of_precision(r, sats, ellipsoid=sphere)
    assert d.vdop == pytest.approx(math.sqrt(D[2, 2]), rel=1e-9)
    assert d.hdop == pytest.approx(math.sqrt(D[0, 0] + D[1, 1]), rel=1e-9)


# --- constellation -------------------------------------------------------------------------


def test_inclination_argument_sets_the_largest_latitude_of_the_ground_track():
    """Oracle: closed form. A circular orbit of inclination i reaches z = R sin i (the
    Earth's rotation about z does not change z)."""
    c = nominal_gps_constellation(inclination_deg=30.0)
    t = np.linspace(0.0, 2 * math.pi / c.mean_motion, 4001)
    z_over_r = c.positions_ecef(t)[..., 2] / c.radius
    assert z_over_r.max() == pytest.approx(math.sin(math.radians(30.0)), rel=1e-5)


def test_elevation_azimuth_in_degrees_matches_pymap3d():
    """Oracle: pymap3d.ecef2aer."""
    lat, lon = 30.0, 60.0
    r = geodetic_to_ecef(lat, lon, 0.0, deg=True)
    sats = nominal_gps_constellation().positions_ecef(0.0)
    el, az = elevation_azimuth(r, sats, lat, lon, deg=True)
    az_o, el_o, _ = pymap3d.ecef2aer(sats[:, 0], sats[:, 1], sats[:, 2], lat, lon, 0.0)
    np.testing.assert_allclose(el, el_o, atol=1e-9)
    np.testing.assert_allclose(np.mod(az, 360.0), np.mod(az_o, 360.0), atol=1e-9)


@pytest.mark.parametrize("deg", [True, False])
def test_visible_matches_pymap3d_elevations(deg):
    """Oracle: pymap3d.ecef2aer elevations against the mask (degrees whatever ``deg``)."""
    c = nominal_gps_constellation()
    sats = c.positions_ecef(1234.0)
    lat, lon = 48.0, 11.0
    _, el_o, _ = pymap3d.ecef2aer(sats[:, 0], sats[:, 1], sats[:, 2], lat, lon, 500.0)
    for mask in (5.0, 25.0):
        args = (lat, lon) if deg else (math.radians(lat), math.radians(lon))
        got = visible(c, 1234.0, *args, 500.0, mask_deg=mask, deg=deg)
        assert got.tolist() == (el_o >= mask).tolist()
        assert 0 < got.sum() < len(sats)


# --- jammer_geometry -----------------------------------------------------------------------


def test_threshold_range_overflow_limit_is_1e300_m():
    """Oracle: the Friis threshold range d = lambda / (4 pi) 10^((ERP + G - J) / 20), its
    decimal exponent placed 0.05 either side of 300."""
    lam, gain, jt = 0.19, 10.0, -150.0
    for decades, raises in ((299.95, False), (300.05, True)):
        erp = 20.0 * (decades - math.log10(lam / (4 * math.pi))) - gain + jt
        if raises:
            with pytest.raises(ValueError, match="1e300"):
                threshold_range_m(erp, jt, lam, rx_gain_dbi=gain)
        else:
            d = threshold_range_m(erp, jt, lam, rx_gain_dbi=gain)
            assert d == pytest.approx(10.0**decades, rel=1e-9)


def test_jitter_defaults_are_the_documented_ones():
    """Oracle: Kaplan & Hegarty Sec. 5.6.1-5.6.2, sigma_phi^2 = Bn/c (1 + 1/(2 T c)) and
    sigma_DLL^2 = Bn d/(2c) (1 + 2/(T c (2 - d))), at T = 20 ms and d = 1 chip; at 20 dB-Hz
    the squaring-loss terms are a few per cent."""
    c = 10.0**2.0
    assert pll_thermal_jitter_deg(20.0, 5.0) == pytest.approx(
        math.degrees(math.sqrt(5.0 / c * (1.0 + 1.0 / (2.0 * 0.02 * c)))), rel=1e-12
    )
    assert dll_thermal_jitter_chips(20.0, 0.5) == pytest.approx(
        math.sqrt(0.5 * 1.0 / (2.0 * c) * (1.0 + 2.0 / (0.02 * c * 1.0))), rel=1e-12
    )
    with pytest.raises(ValueError, match="spacing_chips"):
        dll_thermal_jitter_chips(40.0, 0.5, spacing_chips=0.0)


@pytest.mark.parametrize(
    "call",
    [
        lambda: pll_thermal_jitter_deg(4000.0, 5.0),
        lambda: dll_thermal_jitter_chips(4000.0, 0.5),
        lambda: code_tracking_sigma_chips(4000.0),
    ],
)
def test_an_overflowing_cn0_is_named(call):
    """Oracle: the contract that an error names the parameter as the caller spelled it."""
    with pytest.raises(ValueError, match=r"^cn0_dbhz must be at most"):
        call()


def test_hysteresis_edges():
    """Oracle: the rule read by hand, sample by sample."""
    undecided = [[False], [False]]
    assert hysteresis_from_conditions(undecided, undecided)[:, 0].tolist() == [True, True]
    # decided at the first sample: lost there, regained at the second
    out = hysteresis_from_conditions([[True], [False]], [[False], [True]], initially_locked=True)
    assert out[:, 0].tolist() == [False, True]
    out = hysteresis_from_conditions([[False], [False]], [[True], [False]], initially_locked=False)
    assert out[:, 0].tolist() == [True, True]
    # 0/1 integers are conditions too, and the result is boolean
    out = hysteresis_from_conditions([[0, 1], [1, 0], [0, 0]], [[1, 0], [0, 0], [1, 1]])
    assert out.dtype == np.bool_
    assert out.tolist() == [[True, False], [False, False], [True, True]]


# --- measurements, antijam -----------------------------------------------------------------


def test_shape_errors_name_the_parameter():
    """Oracle: the contract that an error names the parameter as the caller spelled it."""
    r, v = np.zeros(3), np.zeros(3)
    good = np.array([[2e7, 0.0, 0.0]])
    bad = np.ones((1, 2))
    with pytest.raises(ValueError, match=r"^r_sat must have shape"):
        pseudorange(r, bad)
    with pytest.raises(ValueError, match=r"^r_sat must have shape"):
        pseudorange_rate(r, v, bad, good)
    with pytest.raises(ValueError, match=r"^v_sat must have shape"):
        pseudorange_rate(r, v, good, bad)


def test_spectral_separation_series_branch():
    """Oracle: mpmath's quadrature of sinc^2 over (-x, x) at 30 digits, Q = 2x / integral; for
    a jammer 1e-4 of the chip rate wide Q - 1 is about 8e-9, which the series must carry."""
    mpmath.mp.dps = 30
    rc = 1.023e6
    for ratio in (1e-4, 1.9e-4):
        x = mpmath.mpf(ratio) / 2
        integral = mpmath.quad(
            lambda u: (mpmath.sin(mpmath.pi * u) / (mpmath.pi * u)) ** 2 if u else 1, [-x, 0, x]
        )
        q = 2 * x / integral
        assert spectral_separation_q(ratio * rc, rc) - 1.0 == pytest.approx(float(q - 1), rel=1e-5)


# --- satellite priority --------------------------------------------------------------------


def _greedy_oracle(sats: np.ndarray, lat: float, lon: float, h: float, mask_deg: float) -> list[int]:
    """Oracle: pymap3d elevations and lines of sight, then the greedy rule from its definition
    (highest first, then the largest det(G'G + 1e-3 I), determinants, not log-determinants)."""
    _, el, _ = pymap3d.ecef2aer(sats[:, 0], sats[:, 1], sats[:, 2], lat, lon, h)
    vis = np.flatnonzero(el >= mask_deg)
    r = np.array(pymap3d.geodetic2ecef(lat, lon, h))
    u = (sats[vis] - r) / np.linalg.norm(sats[vis] - r, axis=1, keepdims=True)
    G = np.hstack([-u, np.ones((len(vis), 1))])
    order = [int(np.argmax(el[vis]))]
    while len(order) < len(vis):
        dets = {
            c: np.linalg.det(G[[*order, c]].T @ G[[*order, c]] + 1e-3 * np.eye(4))
            for c in range(len(vis))
            if c not in order
        }
        order.append(max(dets, key=dets.get))
    return vis[order].tolist()


def test_satellite_priority_matches_the_greedy_rule_at_seeded_places():
    """Oracle: :func:`_greedy_oracle`, at five seeded receivers, with the default mask (0)."""
    from navcore.gnss.dop import satellite_priority

    rng = np.random.default_rng(11)
    c = nominal_gps_constellation()
    for lat, lon, t in zip(
        rng.uniform(-70, 70, 5), rng.uniform(-180, 180, 5), rng.uniform(0, 43_200, 5), strict=True
    ):
        sats = c.positions_ecef(t)
        assert satellite_priority(sats, lat, lon, 100.0, deg=True).tolist() == _greedy_oracle(
            sats, lat, lon, 100.0, 0.0
        )


def test_satellite_priority_edges():
    """Oracle: closed form (a satellite displaced along y from a receiver on the equator at
    longitude 0 is at elevation exactly 0, one along x at the zenith) and the documented contract."""
    from navcore.gnss.dop import satellite_priority

    sats = np.array(
        [[6378137.0, 2e7, 0.0], [2.6e7, 0.0, 0.0], [2e7, 1e7, 1e7], [2e7, -1e7, 1e7], [2e7, 0.0, -1e7]]
    )
    assert sorted(satellite_priority(sats, 0.0, 0.0, 0.0).tolist()) == [0, 1, 2, 3, 4]
    assert satellite_priority(sats, 0.0, 0.0, 0.0, mask=89.99, deg=True).tolist() == [1]  # the zenith
    assert satellite_priority(sats[[0, 2, 3, 4]], 0.0, 0.0, 0.0, mask=89.99, deg=True).tolist() == []
    with pytest.raises(ValueError, match=r"^r_sat must be a 2-dimensional array"):
        satellite_priority(sats[0], 0.0, 0.0, 0.0)
