"""Normal gravity (issue 30, item 6).

Oracles: the published WGS-84 and GRS-80 normal-gravity constants (computed by the library
from the four defining constants, not typed in); the GRS-80 series expansion of Moritz
(1980); Bruns' formula for the vertical gradient; finite differences.
"""

from __future__ import annotations

import numpy as np
import pytest

from navcore.frames import GRS80, WGS84, Ellipsoid, radii_of_curvature
from navcore.gravity import free_air_gradient, normal_gravity, normal_gravity_at_equator_and_pole
from navcore.units import G0


def test_wgs84_equator_and_pole_against_tr8350():
    """Oracle: NIMA TR8350.2 Table 3.4, gamma_e = 9.7803253359 and gamma_p = 9.8321849378
    m/s^2, printed to 10 decimals. The equator agrees to half a unit of the last digit; the
    closed form gives gamma_p = 9.83218493786, one unit above the printed ...378 in the tenth
    decimal (the table truncates rather than rounds), so the pole is checked to one unit."""
    ge, gp = normal_gravity_at_equator_and_pole()
    assert ge == pytest.approx(9.7803253359, abs=0.5e-10)
    assert gp == pytest.approx(9.8321849378, abs=1.0e-10)
    g = normal_gravity(np.array([0.0, 90.0, -90.0]), deg=True)
    np.testing.assert_allclose(g, [ge, gp, gp], rtol=1e-15)


def test_grs80_equator_and_pole_against_moritz():
    """Oracle: Moritz, Geodetic Reference System 1980: gamma_e = 9.7803267715 and
    gamma_p = 9.8321863685 m/s^2 (to half a unit in the tenth decimal)."""
    ge, gp = normal_gravity_at_equator_and_pole(GRS80)
    assert ge == pytest.approx(9.7803267715, abs=0.5e-10)
    assert gp == pytest.approx(9.8321863685, abs=0.5e-10)


def test_somigliana_against_the_grs80_series():
    """Oracle: Moritz (1980) series gamma_e (1 + 0.0052790414 s^2 + 0.0000232718 s^4 +
    0.0000001262 s^6 + 0.0000000007 s^8), s = sin(lat), accurate to 1e-9 m/s^2 (0.1 microGal)."""
    lat = np.linspace(-np.pi / 2, np.pi / 2, 37)
    s2 = np.sin(lat) ** 2
    series = 9.7803267715 * (
        1 + 0.0052790414 * s2 + 0.0000232718 * s2**2 + 0.0000001262 * s2**3 + 7e-10 * s2**4
    )
    np.testing.assert_allclose(normal_gravity(lat, ellipsoid=GRS80), series, atol=1e-9)


@pytest.mark.parametrize("lat_deg", [0.0, 20.0, 45.0, 70.0, 90.0])
def test_free_air_gradient_against_bruns(lat_deg):
    """Oracle: Bruns' formula for the normal field, d gamma/dh = -2 gamma J - 2 omega^2 with J
    the mean curvature (1/M + 1/N)/2 of the ellipsoid. The TR8350.2 expansion drops terms of
    order f^2 and f m (about 1e-5), so the gradient agrees to 1e-4 relative; it is close to the
    textbook free-air gradient 0.3086 mGal/m (3.086e-6 s^-2) everywhere (within 0.1 %)."""
    g = float(normal_gravity(lat_deg, deg=True))
    R_N, R_E = radii_of_curvature(lat_deg, deg=True)
    bruns = -2.0 * g * 0.5 * (1.0 / R_N + 1.0 / R_E) - 2.0 * WGS84.omega**2
    grad = float(free_air_gradient(lat_deg, deg=True))
    assert grad == pytest.approx(bruns, rel=1e-4)
    assert grad == pytest.approx(-3.086e-6, rel=1e-3)


def test_height_dependence_matches_its_gradient():
    """Oracle: central finite differences of normal_gravity in h (step 1 m) at 0 to 30 km."""
    h = np.array([0.0, 1000.0, 10_000.0, 30_000.0])
    lat = 0.7
    fd = (normal_gravity(lat, h + 1.0) - normal_gravity(lat, h - 1.0)) / 2.0
    np.testing.assert_allclose(free_air_gradient(lat, h), fd, rtol=1e-8)


def test_height_defaults_to_the_ellipsoid_surface():
    """``h`` defaults to 0 in both functions. Oracle: the same calls with ``h=0.0`` spelled out
    (the gradient's height term, 6 gamma h / a^2, is 5e-7 of it at 1 m: visible at rtol 1e-12)."""
    for lat in (0.2, 1.1):
        assert free_air_gradient(lat) == pytest.approx(float(free_air_gradient(lat, 0.0)), rel=1e-12)
        assert normal_gravity(lat) == pytest.approx(float(normal_gravity(lat, 0.0)), rel=1e-15)
    assert free_air_gradient(0.2) != pytest.approx(float(free_air_gradient(0.2, 1.0)), rel=1e-12)


def test_constant_standard_gravity_error():
    """The constant G0 is 2.7 mg above normal gravity at the equator and 2.6 mg below it at
    the poles (the figures the module docstring quotes)."""
    ge, gp = normal_gravity_at_equator_and_pole()
    assert (G0 - ge) / G0 * 1e3 == pytest.approx(2.7, abs=0.05)
    assert (G0 - gp) / G0 * 1e3 == pytest.approx(-2.6, abs=0.05)


def test_bad_input_raises_naming_the_argument():
    with pytest.raises(ValueError, match=r"lat must be a latitude.*deg=True"):
        normal_gravity(48.0)
    with pytest.raises(ValueError, match="h must be in"):
        normal_gravity(0.5, 1e6)
    with pytest.raises(ValueError, match="ellipsoid must be flattened"):
        normal_gravity(0.5, ellipsoid=Ellipsoid("sphere", 6.371e6, 0.0))
    with pytest.raises(ValueError, match=r"Ellipsoid\.f must lie"):
        Ellipsoid("bad", 6.4e6, 1.5)
