"""Units: each conversion factor checked against an independent definition.

Oracles: exact SI definitions (international foot 0.3048 m, nautical mile 1852 m, statute
mile 5280 ft), and scipy.constants for c and g0.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.constants as sc

from navcore import units as u


def test_constants_match_scipy_constants():
    """Oracle: scipy.constants (CODATA)."""
    assert u.C == sc.c
    assert u.G0 == sc.g
    assert u.NMI == sc.nautical_mile
    assert u.FT == pytest.approx(sc.foot, rel=1e-15)
    assert u.MILE == pytest.approx(sc.mile, rel=1e-15)


def test_speed_and_rate_units():
    """Oracle: definitions (1 knot = 1 nmi/h; mph = 5280 ft per hour)."""
    assert u.KNOT == pytest.approx(1852 / 3600)
    assert u.NMI_PER_H == u.KNOT
    assert u.MPH == pytest.approx(5280 * 0.3048 / 3600)
    assert 1.0 * u.DEG_PER_H == pytest.approx(math.radians(1) / 3600)
    assert u.ARCSEC == pytest.approx(math.radians(1 / 3600))
    assert 100 * u.MICRO_G == pytest.approx(100e-6 * 9.80665)


def test_random_walk_units():
    """Oracle: 1 deg/sqrt(h) = (pi/180) rad / sqrt(3600 s); 1 deg/h/sqrt(Hz) = (pi/180)/3600 rad/sqrt(s)."""
    assert u.DEG_PER_SQRT_H == pytest.approx(math.pi / 180 / 60)
    assert u.DEG_PER_H_PER_SQRT_HZ == pytest.approx(math.pi / 180 / 3600)
    # an ARW of 1 deg/sqrt(h) is 60 deg/h/sqrt(Hz)
    assert u.DEG_PER_SQRT_H / u.DEG_PER_H_PER_SQRT_HZ == pytest.approx(60.0)


def test_gps_l1_wavelength():
    """Oracle: lambda = c / f with f = 154 x 10.23 MHz."""
    assert u.GPS_L1_HZ == pytest.approx(154 * 10.23e6)
    assert u.GPS_L1_WAVELENGTH_M == pytest.approx(0.19029, abs=1e-5)
    assert u.GPS_CA_CHIP_M == pytest.approx(293.05, abs=0.01)


@pytest.mark.parametrize("ratio", [1e-30, 0.5, 1.0, 100.0, 1e12])
def test_db_round_trip(ratio):
    """Oracle: round trip power ratio -> dB -> power ratio, and 20 dB = factor 100."""
    assert u.power_ratio_from_db(u.db_from_power_ratio(ratio)) == pytest.approx(ratio, rel=1e-12)
    assert u.amplitude_ratio_from_db(u.db_from_amplitude_ratio(ratio)) == pytest.approx(ratio, rel=1e-12)
    assert u.power_ratio_from_db(20.0) == pytest.approx(100.0)
    assert u.watts_from_dbw(u.dbw_from_watts(ratio)) == pytest.approx(ratio, rel=1e-12)


def test_db_vectorised():
    out = u.db_from_power_ratio(np.array([1.0, 10.0, 100.0]))
    np.testing.assert_allclose(out, [0.0, 10.0, 20.0])


@pytest.mark.parametrize("bad", [0.0, -1.0, float("nan")])
def test_db_rejects_nonpositive(bad):
    with pytest.raises(ValueError, match=r"ratio must be (> 0|finite)"):
        u.db_from_power_ratio(bad)
    with pytest.raises(ValueError, match=r"power_w must be (> 0|finite)"):
        u.dbw_from_watts(bad)


@pytest.mark.parametrize(
    ("convert", "name", "per_decade"),
    [
        (u.power_ratio_from_db, "db", 10.0),
        (u.amplitude_ratio_from_db, "db", 20.0),
        (u.watts_from_dbw, "power_dbw", 10.0),
    ],
)
def test_from_db_accepts_its_range_to_the_last_float_and_names_itself_beyond(convert, name, per_decade):
    """Oracle: the definition 10**(x / per_decade) evaluated by math.pow at the ends of
    [-MAX_DB, MAX_DB], and the documented rejection just beyond them (the next float out),
    whose message names the parameter as the caller spells it."""
    for x in (u.MAX_DB, -u.MAX_DB):
        assert convert(x) == pytest.approx(math.pow(10.0, x / per_decade), rel=1e-12)
        beyond = math.nextafter(x, math.copysign(math.inf, x))
        with pytest.raises(ValueError, match=rf"^{name} must lie in \[-3000, 3000\] dB"):
            convert(beyond)
    with pytest.raises(ValueError, match=rf"^{name} must lie in"):
        convert(np.array([0.0, 2 * u.MAX_DB]))  # one element of an array is enough


def test_amplitude_db_rejects_a_nonpositive_ratio_by_name():
    """Oracle: the documented domain of db_from_amplitude_ratio (a ratio > 0)."""
    with pytest.raises(ValueError, match=r"^ratio must be > 0"):
        u.db_from_amplitude_ratio(0.0)
    assert u.db_from_amplitude_ratio(10.0) == pytest.approx(20.0, rel=1e-15)


@pytest.mark.parametrize(
    ("convert", "x", "expected"),
    [
        (u.db_from_power_ratio, 1000.0, 30.0),
        (u.db_from_amplitude_ratio, 1000.0, 60.0),
        (u.dbw_from_watts, 0.001, -30.0),
        (u.power_ratio_from_db, -30.0, 0.001),
        (u.amplitude_ratio_from_db, -60.0, 0.001),
        (u.watts_from_dbw, 30.0, 1000.0),
    ],
)
def test_scalars_give_floats_and_arrays_keep_their_shape(convert, x, expected):
    """Oracle: decades written out (10 dB per decade of power, 20 dB per decade of amplitude)."""
    out = convert(x)
    assert type(out) is float and out == pytest.approx(expected, rel=1e-14)
    grid = convert(np.full((2, 3), x))
    assert isinstance(grid, np.ndarray) and grid.shape == (2, 3)
    np.testing.assert_allclose(grid, expected, rtol=1e-14)
    assert convert(np.array([x]))[0] == pytest.approx(expected, rel=1e-14)


@pytest.mark.parametrize("convert", [u.power_ratio_from_db, u.amplitude_ratio_from_db, u.watts_from_dbw])
def test_from_db_of_an_empty_array_is_empty(convert):
    out = convert(np.array([]))
    assert isinstance(out, np.ndarray) and out.shape == (0,)
