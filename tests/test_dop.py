"""Dilution of precision (issue 30, item 2).

Oracles: an own weighted least-squares covariance (G' W G)^-1 written from the definition,
with the lines of sight rebuilt from pymap3d's azimuth and elevation; closed forms for two
textbook geometries (a regular tetrahedron, the minimum-GDOP four-satellite geometry, and one
satellite at the zenith with three on the horizon).
"""

from __future__ import annotations

import math

import numpy as np
import pymap3d
import pytest

from navcore.frames import geodetic_to_ecef
from navcore.gnss.constellation import nominal_gps_constellation
from navcore.gnss.dop import dilution_of_precision, dop_from_lines_of_sight


def _own_dop(u_ned: np.ndarray, w: np.ndarray) -> dict[str, float]:
    """Weighted least squares for (north, east, down, clock) from the definition."""
    G = np.column_stack([-u_ned, np.ones(len(u_ned))])
    D = np.linalg.inv(G.T @ np.diag(w) @ G)
    d = np.diag(D)
    return {
        "gdop": math.sqrt(d.sum()),
        "pdop": math.sqrt(d[:3].sum()),
        "hdop": math.sqrt(d[:2].sum()),
        "vdop": math.sqrt(d[2]),
        "tdop": math.sqrt(d[3]),
    }


def _ned_from_aer(az_deg: np.ndarray, el_deg: np.ndarray) -> np.ndarray:
    az, el = np.radians(az_deg), np.radians(el_deg)
    return np.column_stack([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), -np.sin(el)])


def test_regular_tetrahedron_closed_form():
    """Oracle: closed form. A regular tetrahedron (zenith and three satellites at
    elevation -asin(1/3), 120 deg apart) has sum u = 0 and sum u u' = (4/3) I, so
    G'G = diag(4/3, 4/3, 4/3, 4): GDOP = sqrt(10/4), PDOP = 1.5, HDOP = sqrt(1.5),
    VDOP = sqrt(3/4), TDOP = 1/2 (the smallest GDOP four satellites can have)."""
    el = -math.degrees(math.asin(1.0 / 3.0))
    u = _ned_from_aer(np.array([0.0, 0.0, 120.0, 240.0]), np.array([90.0, el, el, el]))
    d = dop_from_lines_of_sight(u)
    assert float(d.gdop) == pytest.approx(math.sqrt(2.5), rel=1e-12)
    assert float(d.pdop) == pytest.approx(1.5, rel=1e-12)
    assert float(d.hdop) == pytest.approx(math.sqrt(1.5), rel=1e-12)
    assert float(d.vdop) == pytest.approx(math.sqrt(0.75), rel=1e-12)
    assert float(d.tdop) == pytest.approx(0.5, rel=1e-12)


def test_zenith_and_horizon_closed_form():
    """Oracle: closed form by hand: zenith plus three on the horizon 120 deg apart gives
    G'G = [[1.5,0,0,0],[0,1.5,0,0],[0,0,1,1],[0,0,1,4]], so HDOP^2 = 4/3, VDOP^2 = 4/3,
    TDOP^2 = 1/3."""
    u = _ned_from_aer(np.array([0.0, 0.0, 120.0, 240.0]), np.array([90.0, 0.0, 0.0, 0.0]))
    d = dop_from_lines_of_sight(u)
    assert (float(d.hdop), float(d.vdop), float(d.tdop)) == pytest.approx(
        (math.sqrt(4 / 3), math.sqrt(4 / 3), math.sqrt(1 / 3)), rel=1e-12
    )


@pytest.mark.parametrize("lat_deg", [0.0, 48.0, -70.0])
def test_constellation_dop_with_mask_and_weights_against_own_least_squares(lat_deg):
    """Oracle: own WLS covariance with lines of sight from pymap3d ecef2aer (azimuth and
    elevation at the receiver), the mask applied by dropping satellites, the weights the
    inverse of an elevation-dependent variance 1/sin(el)^2."""
    r = geodetic_to_ecef(lat_deg, 11.0, 300.0, deg=True)
    sats = nominal_gps_constellation().positions_ecef(1800.0)
    az, el, _ = pymap3d.ecef2aer(sats[:, 0], sats[:, 1], sats[:, 2], lat_deg, 11.0, 300.0)
    u = _ned_from_aer(np.asarray(az), np.asarray(el))
    w = np.sin(np.radians(np.clip(el, 1.0, 90.0))) ** 2
    for mask in (0.0, 10.0, 15.0):
        keep = np.asarray(el) >= mask
        exp = _own_dop(u[keep], w[keep])
        d = dilution_of_precision(r, sats, mask=mask, weights=w, deg=True)
        for name, value in exp.items():
            assert float(getattr(d, name)) == pytest.approx(value, rel=1e-9), (mask, name)
        assert int(d.n_used) == int(keep.sum())
    d = dilution_of_precision(r, sats, mask=np.radians(10.0), weights=w)  # radians by default
    assert float(d.pdop) == pytest.approx(
        _own_dop(u[np.asarray(el) >= 10.0], w[np.asarray(el) >= 10.0])["pdop"]
    )


def test_stacks_of_epochs_and_receivers():
    """Oracle: the same function one geometry at a time: a (T, K, 3) stack of satellite
    positions (epochs) from one receiver, and (M, 3) receivers against one constellation."""
    c = nominal_gps_constellation()
    sats_t = c.positions_ecef(np.arange(0.0, 3600.0, 600.0))  # (6, 24, 3)
    r = geodetic_to_ecef(45.0, 7.0, 0.0, deg=True)
    d = dilution_of_precision(r, sats_t, mask=5.0, deg=True)
    assert d.pdop.shape == (6,)
    for i in range(6):
        assert float(d.pdop[i]) == pytest.approx(
            float(dilution_of_precision(r, sats_t[i], mask=5.0, deg=True).pdop)
        )
    receivers = geodetic_to_ecef(np.array([0.0, 30.0, 60.0]), np.array([0.0, 40.0, 80.0]), 0.0, deg=True)
    d = dilution_of_precision(receivers, sats_t[0], mask=5.0, deg=True)
    assert d.gdop.shape == (3,)
    for i in range(3):
        assert float(d.gdop[i]) == pytest.approx(
            float(dilution_of_precision(receivers[i], sats_t[0], mask=5.0, deg=True).gdop)
        )


def test_too_few_satellites_give_infinite_dop_not_nan():
    """Three satellites (or four coplanar with the clock column) have no solution: every DOP
    is infinite, never NaN."""
    u = _ned_from_aer(np.array([0.0, 120.0, 240.0]), np.array([30.0, 30.0, 30.0]))
    d = dop_from_lines_of_sight(u)
    assert all(math.isinf(float(getattr(d, k))) for k in ("gdop", "pdop", "hdop", "vdop", "tdop"))
    u4 = _ned_from_aer(np.array([0.0, 90.0, 180.0, 270.0]), np.array([30.0, 30.0, 30.0, 30.0]))
    assert math.isinf(float(dop_from_lines_of_sight(u4).vdop))  # same elevation: height and clock mix
    d = dop_from_lines_of_sight(u4, weights=[1.0, 1.0, 1.0, 0.0])
    assert int(d.n_used) == 3 and math.isinf(float(d.pdop))


def test_positions_are_not_lines_of_sight():
    """Issue 30, case 5: satellite positions in metres are rejected, naming the argument."""
    sats = nominal_gps_constellation().positions_ecef(0.0)[:6]
    with pytest.raises(ValueError, match="u_ned must hold unit lines of sight"):
        dop_from_lines_of_sight(sats)
    with pytest.raises(ValueError, match="weights must be >= 0"):
        dop_from_lines_of_sight(sats / np.linalg.norm(sats, axis=1)[:, None], weights=-np.ones(6))
    with pytest.raises(ValueError, match="mask must be an elevation"):
        dilution_of_precision(geodetic_to_ecef(0.0, 0.0, 0.0), sats, mask=15.0)


def test_satellite_priority_orders_the_visible_satellites_greedily():
    """Oracle: elevations from pymap3d (an independent geodesy library): the list holds exactly
    the satellites at or above the mask, highest first; each later satellite maximises
    det(G'G + 1e-3 I) of the chosen ones, by brute force over the remaining ones (determinants,
    not log-determinants); degrees and radians give one order."""
    from navcore.gnss.dop import satellite_priority

    lat, lon, h, mask = 35.0, -100.0, 300.0, 10.0
    sats = nominal_gps_constellation().positions_ecef(0.0)
    order = satellite_priority(sats, lat, lon, h, mask=mask, deg=True)
    _, el, _ = pymap3d.ecef2aer(sats[:, 0], sats[:, 1], sats[:, 2], lat, lon, h)
    assert sorted(order.tolist()) == np.flatnonzero(el >= mask).tolist()
    assert order[0] == int(np.argmax(np.where(el >= mask, el, -90.0)))
    r = geodetic_to_ecef(lat, lon, h, deg=True)
    u = (sats - r) / np.linalg.norm(sats - r, axis=1, keepdims=True)
    G = np.hstack([-u, np.ones((len(sats), 1))])
    for k in range(1, len(order)):
        dets = {
            c: np.linalg.det(G[[*order[:k], c]].T @ G[[*order[:k], c]] + 1e-3 * np.eye(4)) for c in order[k:]
        }
        assert order[k] == max(dets, key=dets.get)
    same = satellite_priority(sats, math.radians(lat), math.radians(lon), h, mask=math.radians(mask))
    assert same.tolist() == order.tolist()


def test_satellite_priority_rejects_bad_arguments():
    from navcore.gnss.dop import satellite_priority

    sats = nominal_gps_constellation().positions_ecef(0.0)
    with pytest.raises(ValueError, match="r_sat"):
        satellite_priority(sats[:, :2], 0.5, 0.1, 0.0)
    with pytest.raises(ValueError, match="lat"):
        satellite_priority(sats, 2.0, 0.1, 0.0)
    with pytest.raises(ValueError, match="mask"):
        satellite_priority(sats, 0.5, 0.1, 0.0, mask=100.0, deg=True)
