"""Multilateration geometry against independent constructions (pymap3d, brute force)."""

from __future__ import annotations

import math

import numpy as np
import pymap3d
import pytest

from navcore.location.multilateration import (
    EARTH_MEAN_RADIUS_M,
    beta_parameter,
    clock_direction_term,
    constellation_parameters,
    frame_dependent_clock_term,
    line_of_sight_matrix,
    most_widely_spaced_triplet,
    position_dilution,
    position_dilution_covariance,
    position_on_sphere,
    position_trace,
    synchronous_orbit_radius,
    zenith_angles,
)

SATS_I = np.array(
    [(14.9, 152.7), (63.4, 115.0), (36.6, 101.8), (51.0, 123.2), (51.0, 106.8), (60.1, 80.5), (60.1, 79.5)]
)
R_RATIO = 42_164.17 / 6371.0


def _geometry(ratio: float = R_RATIO):
    sats = position_on_sphere(SATS_I[:, 0], SATS_I[:, 1], ratio * EARTH_MEAN_RADIUS_M, deg=True)
    ac = position_on_sphere(45.0, 120.0, EARTH_MEAN_RADIUS_M, deg=True)
    return sats, ac


def test_synchronous_radius_force_balance():
    """Oracle: at the synchronous radius gravity GM/r^2 supplies the centripetal acceleration
    (2 pi / T)^2 r of a body turning once per period T; with the WGS-84 GM and the sidereal
    day (86 164.0905 s) that is the textbook 42 164 km, and for another GM and period the
    same balance holds."""
    gm, day = 3.986004418e14, 86_164.0905
    r = synchronous_orbit_radius()
    assert gm / r**2 == pytest.approx((2 * math.pi / day) ** 2 * r, rel=1e-9)
    assert r == pytest.approx(42_164.17e3, rel=1e-6)
    r2 = synchronous_orbit_radius(gm=4.9e12, period_s=3600.0)
    assert 4.9e12 / r2**2 == pytest.approx((2 * math.pi / 3600.0) ** 2 * r2, rel=1e-12)


def test_positions_match_pymap3d_sphere():
    """Oracle: pymap3d geodetic2ecef on a spherical ellipsoid (altitude = r - R)."""
    sphere = pymap3d.Ellipsoid(EARTH_MEAN_RADIUS_M, EARTH_MEAN_RADIUS_M)
    sats, _ = _geometry()
    for (lat, lon), s in zip(SATS_I, sats, strict=True):
        ref = pymap3d.geodetic2ecef(lat, lon, (R_RATIO - 1.0) * EARTH_MEAN_RADIUS_M, ell=sphere)
        np.testing.assert_allclose(s, ref, rtol=1e-12, atol=1e-3)


def test_zenith_angles_match_pymap3d_elevation():
    """Oracle: pymap3d ecef2aer elevation; zenith = 90 deg - elevation."""
    sphere = pymap3d.Ellipsoid(EARTH_MEAN_RADIUS_M, EARTH_MEAN_RADIUS_M)
    sats, ac = _geometry()
    zen = zenith_angles(ac, sats, deg=True)
    for s, z in zip(sats, zen, strict=True):
        _, el, _ = pymap3d.ecef2aer(*s, 45.0, 120.0, 0.0, ell=sphere)
        assert z == pytest.approx(90.0 - float(el), abs=1e-9)


def test_invariants_match_pymap3d_enu_frame():
    """Oracle: unit vectors rebuilt in the local ENU frame from pymap3d azimuth/elevation.

    beta, tr{(F'F)^-1}, S and the K = 3 invariant are rotation invariant; the printed
    K = 3 term 1'(F'F)^-1 1 is not.
    """
    sphere = pymap3d.Ellipsoid(EARTH_MEAN_RADIUS_M, EARTH_MEAN_RADIUS_M)
    sats, ac = _geometry()
    U = line_of_sight_matrix(ac, sats)
    rows = []
    for s in sats:
        az, el, _ = pymap3d.ecef2aer(*s, 45.0, 120.0, 0.0, ell=sphere)
        az, el = math.radians(float(az)), math.radians(float(el))
        rows.append([math.cos(el) * math.sin(az), math.cos(el) * math.cos(az), math.sin(el)])
    V = np.array(rows)
    for f in (beta_parameter, position_trace, clock_direction_term):
        assert f(U) == pytest.approx(f(V), rel=1e-9)
    assert clock_direction_term(U[:3]) == pytest.approx(clock_direction_term(V[:3]), rel=1e-9)
    assert abs(frame_dependent_clock_term(U[:3]) - frame_dependent_clock_term(V[:3])) > 0.5


def test_k3_clock_term_equals_ffprime_inverse():
    """Oracle: closed form 1'(FF')^-1 1 for a square F."""
    sats, ac = _geometry()
    F = line_of_sight_matrix(ac, sats)[:3]
    assert clock_direction_term(F) == pytest.approx(float(np.ones(3) @ np.linalg.solve(F @ F.T, np.ones(3))))
    assert beta_parameter(F) == pytest.approx(0.0, abs=1e-12)


def test_dilution_any_differencing_matrix():
    """Oracle: Eq. 4.1.1 with random zero-row-sum H equals tr + S/beta (Eq. 4.5.6/4.5.7)."""
    sats, ac = _geometry()
    F = line_of_sight_matrix(ac, sats)
    rng = np.random.default_rng(3)
    K = F.shape[0]
    p = constellation_parameters(F)
    for _ in range(3):
        H = rng.normal(size=(K - 1, K))
        H -= H.mean(axis=1, keepdims=True)
        P = position_dilution_covariance(F, H)
        assert np.trace(P) == pytest.approx(p.trace + p.clock_term / p.beta, rel=1e-9)
    assert position_dilution(F) ** 2 == pytest.approx(np.trace(position_dilution_covariance(F)), rel=1e-9)


def test_beta_brute_force_projection():
    """Oracle: beta = K - 1'F(F'F)^-1F'1 with explicit inverse."""
    sats, ac = _geometry(9.2351)
    F = line_of_sight_matrix(ac, sats)
    one = np.ones(F.shape[0])
    ref = F.shape[0] - one @ F @ np.linalg.inv(F.T @ F) @ F.T @ one
    assert beta_parameter(F) == pytest.approx(ref, rel=1e-9)


def test_triplet_brute_force():
    """Oracle: exhaustive loop over all triplets by smallest trace."""
    sats, ac = _geometry()
    U = line_of_sight_matrix(ac, sats)
    best = min(
        ((i, j, k) for i in range(7) for j in range(i + 1, 7) for k in range(j + 1, 7)),
        key=lambda t: np.trace(np.linalg.inv(U[list(t)].T @ U[list(t)])),
    )
    assert most_widely_spaced_triplet(ac, sats, 90.0, deg=True)[0] == best == (0, 1, 2)
    # inside the 45 deg cone satellite 1 (index 0) is excluded
    assert 0 not in most_widely_spaced_triplet(ac, sats, np.radians(45.0))[0]


def test_bad_input_raises():
    with pytest.raises(ValueError, match="F must"):
        beta_parameter(np.ones((2, 3)))
    with pytest.raises(ValueError, match="criterion"):
        sats, ac = _geometry()
        most_widely_spaced_triplet(ac, sats, 90.0, criterion="bogus", deg=True)


@pytest.mark.parametrize("criterion", ["trace", "det", "angle"])
@pytest.mark.parametrize("cone", [90.0, 60.0, 45.0])
def test_triplet_every_criterion_brute_force(criterion, cone):
    """Oracle: an exhaustive search written from the definitions, on seeded random geometries:
    zenith angles from the spherical local vertical and lines of
    sight computed with numpy, and the three criteria (smallest tr (F'F)^-1, largest |det F|, largest
    smallest pairwise angle) with their scores."""
    import itertools

    rng = np.random.default_rng(13)
    for _ in range(3):
        lat_lon = np.column_stack([rng.uniform(-10, 80, 9), rng.uniform(60, 180, 9)])
        sats = position_on_sphere(lat_lon[:, 0], lat_lon[:, 1], R_RATIO * EARTH_MEAN_RADIUS_M, deg=True)
        ac = position_on_sphere(45.0, 120.0, EARTH_MEAN_RADIUS_M, deg=True)
        d = ac - sats
        U = d / np.linalg.norm(d, axis=1)[:, None]
        up = ac / np.linalg.norm(ac)
        zenith = np.degrees(np.arccos(np.clip(-U @ up, -1, 1)))
        inside = [i for i in range(9) if zenith[i] <= cone + 1e-9]

        def score(t, U=U):
            F = U[list(t)]
            if criterion == "trace":
                return np.trace(np.linalg.inv(F.T @ F))
            if criterion == "det":
                return -abs(np.linalg.det(F))
            return -min(np.degrees(np.arccos(F[i] @ F[j])) for i, j in ((0, 1), (0, 2), (1, 2)))

        best = min(itertools.combinations(inside, 3), key=score)
        tri, value = most_widely_spaced_triplet(ac, sats, cone, criterion, deg=True)
        assert tri == best
        assert value == pytest.approx(abs(score(best)), rel=1e-9)
        np.testing.assert_allclose(zenith_angles(ac, sats, deg=True), zenith, atol=1e-9)
        if criterion == "angle":  # radians by default
            _, rad = most_widely_spaced_triplet(ac, sats, np.radians(cone), criterion)
            assert rad == pytest.approx(np.radians(value), rel=1e-12)


def test_zenith_and_nadir_satellites_and_the_cone_boundary():
    """Oracles: geometry: a satellite straight up the local vertical is at zenith angle 0, one
    straight down at 180 deg; at this place (found by a seeded search) the rounded cosine is
    1 + 2e-16 in magnitude, so it must be clipped. A satellite exactly on the cone (its own
    zenith angle used as the half-angle) is inside ("within the cone" includes the edge)."""
    lat, lon = 21.91386997143269, -82.87678304500669
    ac = position_on_sphere(lat, lon, EARTH_MEAN_RADIUS_M, deg=True)
    up = ac / np.linalg.norm(ac)
    z = zenith_angles(ac, np.array([ac + 3e7 * up, ac - 3e6 * up]), deg=True)
    np.testing.assert_allclose(z, [0.0, 180.0], atol=1e-6)
    sats, ac = _geometry()
    zen = zenith_angles(ac, sats, deg=True)
    k = int(np.argsort(zen)[3])  # the fourth-closest to the vertical
    tri, _ = most_widely_spaced_triplet(ac, sats, float(zen[k]) - 1e-9, deg=True)  # the 1e-9 deg allowance
    assert k in tri
    # the same zenith angle whether the aircraft is given as (3,) or (1, 3)
    np.testing.assert_array_equal(zenith_angles(ac[None, :], sats, deg=True), zen)


def test_coplanar_triplet_has_infinite_trace_and_parameters_dilution():
    """Oracles: three lines of sight in one vertical plane (zero east component) make F
    singular, so the only triplet's trace score is infinite (no position fix); the
    constellation's dilution is sqrt(tr + S/beta) from its own traces (Eq. 4.5.6/4.5.7)."""
    ac = np.array([0.0, 0.0, EARTH_MEAN_RADIUS_M])
    th = np.radians([-30.0, 0.0, 30.0])
    sats = ac + 2e7 * np.column_stack([np.sin(th), np.zeros(3), np.cos(th)])
    tri, score = most_widely_spaced_triplet(ac, sats, 90.0, deg=True)
    assert tri == (0, 1, 2) and score == math.inf
    sats7, ac7 = _geometry()
    p = constellation_parameters(line_of_sight_matrix(ac7, sats7))
    assert p.dilution == pytest.approx(math.sqrt(p.trace + p.clock_term / p.beta), rel=1e-12)


@pytest.mark.parametrize("shape", [(4, 2), (2, 3)])
def test_geometry_matrix_shape_is_checked(shape):
    """Contract: F must be K x 3 with K >= 3 (the shape message, not a later rank failure)."""
    with pytest.raises(ValueError, match="K x 3"):
        position_trace(np.ones(shape))


def test_identical_satellites_have_zero_separation():
    """Oracle: geometry: three satellites at one position (this one, found by a seeded search,
    makes the rounded cosine between the identical lines of sight 1 + 2e-16) are 0 deg apart."""
    _, ac = _geometry()
    s = np.array([19719117.844802145, 37060229.151186995, 2404281.315552615])
    assert most_widely_spaced_triplet(ac, np.array([s, s, s]), 90.0, "angle", deg=True) == ((0, 1, 2), 0.0)


@pytest.mark.parametrize("criterion", ["trace", "det"])
def test_tied_triplets_resolve_to_the_first(criterion):
    """Oracle: an exhaustive search over itertools.combinations with min() (which keeps the
    first of equal scores) on a geometry mirror-symmetric in x and y (found by a seeded
    search): satellites 2 and 3 are mirror images, so the triplets (0, 1, 2) and (0, 1, 3)
    tie exactly; the first in index order is returned."""
    import itertools

    ac = np.array([EARTH_MEAN_RADIUS_M / math.sqrt(2)] * 2 + [0.0])
    sats = np.array(
        [
            [9738881.837548502, 33942647.98374179, 6467029.962018469],
            [33942647.98374179, 9738881.837548502, 6467029.962018469],
            [20145565.6325811, 8374868.191943854, -16480751.708556527],
            [8374868.191943854, 20145565.6325811, -16480751.708556527],
            [18187373.955980718, 18187373.955980718, 1090140.8782154752],
        ]
    )
    U = line_of_sight_matrix(ac, sats)

    def score(t):
        F = U[list(t)]
        return np.trace(np.linalg.inv(F.T @ F)) if criterion == "trace" else -abs(np.linalg.det(F))

    combos = list(itertools.combinations(range(5), 3))
    best = min(combos, key=score)
    ties = [t for t in combos if score(t) == score(best)]
    assert len(ties) >= 2
    assert most_widely_spaced_triplet(ac, sats, 90.0, criterion, deg=True)[0] == best == ties[0]


def test_position_dilution_is_the_pdop_of_the_lines_of_sight():
    """Oracle: an own weighted least-squares covariance of [u, 1] (position and the unknown
    emission time) for ATC-10's Example I geometry: ATC-10's dilution k is that solution's
    PDOP, and navcore.gnss.dop gives the same PDOP from the same lines of sight (sign either
    way: the lines of sight of navcore point from the aircraft to the satellites)."""
    from navcore.gnss.dop import dop_from_lines_of_sight

    sats, ac = _geometry()
    U = line_of_sight_matrix(ac, sats)
    G = np.hstack([U, np.ones((U.shape[0], 1))])
    own = math.sqrt(np.trace(np.linalg.inv(G.T @ G)[:3, :3]))
    assert position_dilution(U) == pytest.approx(own, rel=1e-10)
    assert position_dilution(-U) == pytest.approx(own, rel=1e-10)
    assert float(dop_from_lines_of_sight(U).pdop) == pytest.approx(own, rel=1e-10)


def test_line_of_sight_points_from_the_aircraft_to_the_satellite():
    """Convention: receiver first; unit vectors from it to each satellite (like
    navcore.gnss.constellation.line_of_sight)."""
    from navcore.gnss.constellation import line_of_sight

    sats, ac = _geometry()
    u, _ = line_of_sight(ac, sats)
    np.testing.assert_allclose(line_of_sight_matrix(ac, sats), u, atol=1e-15)
    d = sats - ac
    np.testing.assert_allclose(line_of_sight_matrix(ac, sats), d / np.linalg.norm(d, axis=1)[:, None])
