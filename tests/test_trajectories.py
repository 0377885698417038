"""Trajectory generator (coordinated turns, climbs) against closed-form point-mass kinematics.

Oracle: the analytic acceleration of a point mass at speed V whose heading and flight-path
angle change at chi_dot and gamma_dot, a = V chi_dot cos(gamma) e_h + V gamma_dot e_v
(e_h the horizontal normal, e_v the pitch-down normal of the velocity), minus gravity; a
coordinated turn has no body-y component of this specific force (Etkin, *Dynamics of
Atmospheric Flight*, steady coordinated turn).
"""

from __future__ import annotations

import numpy as np
import pytest

from navcore.inertial.trajectories import Segment, fly
from navcore.units import G0


def _analytic_specific_force(V, chi, gam, chi_dot, gam_dot):
    e_h = np.stack([-np.sin(chi), np.cos(chi), np.zeros_like(chi)], -1)
    e_v = np.stack([-np.sin(gam) * np.cos(chi), -np.sin(gam) * np.sin(chi), -np.cos(gam)], -1)
    a = (V * chi_dot * np.cos(gam))[:, None] * e_h + (V * gam_dot)[:, None] * e_v
    return a - np.array([0.0, 0.0, G0])


@pytest.mark.parametrize(
    ("chi_dot", "gam0", "gam_dot"),
    [(0.03, 0.2, 0.0), (-0.03, -0.25, 0.0), (0.05, 0.0, 0.0), (0.03, 0.1, 0.004), (-0.02, 0.1, -0.01)],
    ids=["climbing-turn", "diving-turn-left", "level-turn", "pull-up-in-turn", "push-over-in-turn"],
)
def test_coordinated_turn_has_no_side_force(chi_dot, gam0, gam_dot):
    """Oracle: body-y of the analytic specific force is zero. The old bank angle
    tan(phi) = V chi_dot cos(gamma) / g left 0.100 m/s^2 at 200 m/s, 0.03 rad/s, 0.2 rad."""
    V, dt = 200.0, 0.1
    tr = fly(
        [Segment(60.0, turn_rate=chi_dot, path_angle_rate=gam_dot)],
        dt=dt,
        speed0=V,
        path_angle0=gam0,
        h0=10000.0,
    )
    t = tr.t[1:-1]  # interior samples (the generator's central differences are exact there)
    chi, gam = chi_dot * t, gam0 + gam_dot * t
    f_n = _analytic_specific_force(np.full(t.size, V), chi, gam, chi_dot, gam_dot)
    y_body = tr.C_bn[1:-1, :, 1]  # body y axis in NED
    side = np.einsum("ni,ni->n", y_body, f_n)
    np.testing.assert_allclose(side, 0.0, atol=1e-9)
    # and the generator's own (numerically differentiated) specific force agrees with the oracle
    np.testing.assert_allclose(tr.f_ned[1:-1], f_n, atol=2e-3)
    # the body x axis lies along the velocity
    x_body = tr.C_bn[:, :, 0]
    np.testing.assert_allclose(x_body, tr.vel_ned / V, atol=1e-12)


def test_issue_climbing_turn_bank_angle():
    """Oracle: tan(phi) = V chi_dot / g for a turn at constant flight-path angle (hand formula)."""
    tr = fly([Segment(10.0, turn_rate=0.03)], dt=1.0, speed0=200.0, path_angle0=0.2)
    roll = np.arctan2(tr.C_bn[:, 2, 1], tr.C_bn[:, 2, 2])  # C[2,1] = cos(pitch) sin(roll)
    np.testing.assert_allclose(roll, np.arctan(200.0 * 0.03 / G0), atol=1e-12)


def test_straight_flight_has_wings_level():
    """Oracle: no turn means no bank, also while pitching (lift stays in the vertical plane)."""
    tr = fly([Segment(20.0, path_angle_rate=0.01), Segment(20.0, path_angle_rate=-0.02)], speed0=150.0)
    np.testing.assert_allclose(tr.C_bn[:, 2, 1], 0.0, atol=1e-15)
