"""INS error dynamics against closed forms (Schuler oscillation, random-walk growth, Markov)."""

from __future__ import annotations

import numpy as np
import pymap3d
import pytest
import scipy.linalg
from _oracles import van_loan_expm

from navcore.frames import dcm_from_euler as fr_dcm
from navcore.inertial.error_dynamics import (
    ClockModel,
    ErrorSources,
    GaussMarkov,
    earth_rate_ned,
    error_dynamics,
    gravity_tuning_psd,
    gyrocompass_alignment,
    initial_covariance,
    ins_error_layout,
    levelling_alignment,
    process_noise_psd,
    schuler_frequency,
    schuler_period,
    skew_stack,
)
from navcore.inertial.imu import ImuSpec
from navcore.inertial.trajectories import straight_and_level
from navcore.integration.engine import run_covariance_analysis
from navcore.units import DEG, DEG_PER_H, G0, MICRO_G, OMEGA_EARTH, WGS84_A

CORE = ins_error_layout("position", "velocity", "misalignment")


def test_schuler_period_closed_form():
    """Oracle: 2 pi sqrt(R/g) with R = 6378137 m, g = 9.80665 m/s^2 (84.4 min)."""
    assert schuler_period() == pytest.approx(2 * np.pi * np.sqrt(WGS84_A / G0), rel=1e-12)
    assert schuler_period() / 60 == pytest.approx(84.45, abs=0.01)
    # the Moon (R = 1737.4 km, g = 1.62 m/s^2): the period of a surface-grazing circular orbit
    assert schuler_period(1.62, 1_737_400.0) / 60 == pytest.approx(108.4, abs=0.1)


def test_schuler_oscillation_period_and_amplitude_from_eigen_and_expm():
    """Oracle: closed form dr_N(t) = dv0 sin(ws t)/ws for an initial velocity error, at the
    equator with the vertical frozen; the model is propagated with scipy.linalg.expm."""
    F = error_dynamics(CORE, f_ned=(0, 0, -G0), C_bn=np.eye(3), lat=0.0, vertical_channel=False)
    ws = schuler_frequency()
    # the eigenvalues of the horizontal position-velocity block are +-j ws (Schuler)
    ev = np.linalg.eigvals(F[np.ix_([0, 3], [0, 3])])
    assert np.sort(np.abs(ev.imag)) == pytest.approx([ws, ws], rel=1e-12)
    x0 = np.zeros(9)
    x0[3] = 1.0
    for t in (600.0, 1266.0, 2533.0, 5067.0):
        x = scipy.linalg.expm(F * t) @ x0
        assert x[0] == pytest.approx(np.sin(ws * t) / ws, rel=2e-3, abs=1e-3)
    # amplitude at a quarter period
    x = scipy.linalg.expm(F * schuler_period() / 4) @ x0
    assert x[0] == pytest.approx(1.0 / ws, rel=1e-3)


def test_accel_bias_and_gyro_drift_closed_forms():
    """Oracles: b/ws^2 (1 - cos ws t) for an accelerometer bias and R eps (t - sin(ws t)/ws)
    for a level gyro drift (Schuler-only closed forms; Earth rate removed at the equator
    for the bias case, 1.5 % allowed for the Earth-rate coupling of the gyro case)."""
    lay = ins_error_layout("position", "velocity", "misalignment", "gyro bias", "accel bias")
    F = error_dynamics(lay, f_ned=(0, 0, -G0), C_bn=np.eye(3), lat=0.0, vertical_channel=False)
    ws = schuler_frequency()
    t = 3600.0
    x0 = np.zeros(lay.size)
    x0[lay.index("accel bias", 0)] = 100 * MICRO_G
    x = scipy.linalg.expm(F * t) @ x0
    assert abs(x[0]) == pytest.approx(100 * MICRO_G / ws**2 * (1 - np.cos(ws * t)), rel=1e-3)
    x0[:] = 0.0
    x0[lay.index("gyro bias", 0)] = 0.01 * DEG_PER_H
    x = scipy.linalg.expm(F * t) @ x0
    assert abs(x[1]) == pytest.approx(WGS84_A * 0.01 * DEG_PER_H * (t - np.sin(ws * t) / ws), rel=0.015)


@pytest.mark.parametrize("t_min", [19.0, 84.0])
def test_angle_random_walk_growth_law(t_min):
    """Oracle: per-axis position variance of a white gyro rate noise N (rad/sqrt(s)) through
    the Schuler loop, R^2 N^2 (1.5 t - 2 sin(ws t)/ws + sin(2 ws t)/(4 ws)). The closed form
    ignores the Earth-rate rotation of the psi angle (Omega t = 0.37 rad at 84 min), which
    the model keeps: 0.2 % allowed at 19 min, 2.5 % at 84 min."""
    N = 4.7 * DEG_PER_H
    src = ErrorSources(imu=ImuSpec("arw", gyro_random_walk=N))
    tr = straight_and_level(t_min * 60, dt=1.0, lat0=0.0)
    res = run_covariance_analysis(tr, CORE, CORE, src, np.zeros((9, 9)), vertical_channel=False)
    ws, t = schuler_frequency(), t_min * 60
    var = WGS84_A**2 * N**2 * (1.5 * t - 2 * np.sin(ws * t) / ws + np.sin(2 * ws * t) / (4 * ws))
    assert res.true_var[-1, 0] == pytest.approx(var, rel=2e-3 if t_min < 30 else 0.025)


def test_velocity_random_walk_growth_law():
    """Oracle: white acceleration noise of PSD q through the Schuler loop gives velocity
    variance q (t/2 + sin(2 ws t)/(4 ws)) and position variance q/ws^2 (t/2 - sin(2 ws t)/(4 ws))."""
    q = (56 * MICRO_G) ** 2
    src = ErrorSources(imu=ImuSpec("vrw", accel_random_walk=np.sqrt(q)))
    tr = straight_and_level(3000.0, dt=1.0, lat0=0.0)
    res = run_covariance_analysis(tr, CORE, CORE, src, np.zeros((9, 9)), vertical_channel=False)
    ws, t = schuler_frequency(), 3000.0
    assert res.true_var[-1, 3] == pytest.approx(q * (t / 2 + np.sin(2 * ws * t) / (4 * ws)), rel=2e-3)
    assert res.true_var[-1, 0] == pytest.approx(q / ws**2 * (t / 2 - np.sin(2 * ws * t) / (4 * ws)), rel=2e-3)


def test_gauss_markov_one_state_variance():
    """Oracle: a first-order Markov process started at zero has variance
    sigma^2 (1 - exp(-2 beta t)) with beta = speed / distance constant."""
    lay = ins_error_layout("position", "velocity", "misalignment", "gravity")
    gm = GaussMarkov(35 * MICRO_G, 37_000.0)
    src = ErrorSources(imu=ImuSpec("none"), gravity=gm)
    tr = straight_and_level(600.0, speed=250.0, dt=1.0)
    res = run_covariance_analysis(tr, lay, lay, src, np.zeros((lay.size, lay.size)), vertical_channel=False)
    beta = 250.0 / 37_000.0
    expect = gm.sigma**2 * (1 - np.exp(-2 * beta * tr.t))
    got = res.true_var[:, lay.index("gravity", 0)]
    assert got == pytest.approx(expect, rel=1e-3, abs=1e-18)


def test_bad_layout_raises():
    with pytest.raises(ValueError, match="layout must contain"):
        error_dynamics(ins_error_layout("position", "velocity"), f_ned=(0, 0, -G0), C_bn=np.eye(3))
    with pytest.raises(ValueError, match="names must be among"):
        ins_error_layout("wobble")


_ATT = (0.3, -0.2, 2.0)  # roll, pitch, yaw: a C_bn that is neither I nor symmetric
_F_B = np.array([1.5, -0.7, -9.5])  # specific force, body axes (m/s^2)
_W_B = np.array([0.05, -0.1, 0.2])  # body rate (rad/s)
_SENSOR_CASES = {
    "accel bias": np.array([1e-3, -2e-3, 3e-3]),
    "accel scale factor": np.array([1e-4, -3e-4, 5e-4]),
    "accel misalignment": np.array([2e-4, -1e-4, 3e-4]),
    "gyro bias": np.array([1e-5, -2e-5, 3e-5]),
    "gyro scale factor": np.array([1e-4, -3e-4, 5e-4]),
    "gyro misalignment": np.array([2e-4, -1e-4, 3e-4]),
}


def _faulty_triad(true_b, block, x):
    """A sensor triad with one error source, modelled from its physical definition: a bias
    adds, a scale factor multiplies each axis, an input-axis misalignment mu means the triad
    measures the components in axes rotated by mu from the body (scipy Rotation)."""
    from scipy.spatial.transform import Rotation

    kind = block.split()[-1]
    if kind in ("bias", "drift"):
        return true_b + x
    if kind == "factor":
        return true_b * (1.0 + x)
    return Rotation.from_rotvec(x).inv().apply(true_b)


@pytest.mark.parametrize("block", list(_SENSOR_CASES))
def test_sensor_couplings_match_strapdown_perturbation(block):
    """Oracle: one short strapdown step (navcore.inertial.strapdown, quaternion attitude) with
    a faulty triad against one with perfect sensors, at a non-level, non-north attitude with
    anisotropic (different per axis) errors: the velocity-error rate and the psi-angle rate
    (C~_bn = (I - [psi x]) C_bn) equal F x on the velocity and misalignment rows. A transposed
    C_bn at either coupling site, or an error rotated with the wrong frame, fails this."""
    from navcore import frames as fr
    from navcore.inertial.strapdown import NavState, dcm_from_quat_batch, strapdown_step

    lay = ins_error_layout("position", "velocity", "misalignment", block)
    C = fr.dcm_from_euler(*_ATT)
    F = error_dynamics(lay, f_ned=C @ _F_B, C_bn=C, omega_ib_b=_W_B, lat=0.7)
    x = _SENSOR_CASES[block]
    dt = 1e-5
    s0 = NavState(np.zeros((1, 3)), np.zeros((1, 3)), fr.quat_from_euler(*_ATT)[None])
    w_true, f_true = _W_B, _F_B
    w_bad = _faulty_triad(_W_B, block, x) if block.startswith("gyro") else _W_B
    f_bad = _faulty_triad(_F_B, block, x) if block.startswith("accel") else _F_B
    good = strapdown_step(s0, w_true[None], f_true[None], dt)
    bad = strapdown_step(s0, w_bad[None], f_bad[None], dt)
    dv_rate = (bad.vel[0] - good.vel[0]) / dt
    E = dcm_from_quat_batch(bad.quat)[0] @ dcm_from_quat_batch(good.quat)[0].T
    psi_rate = np.array([E[1, 2] - E[2, 1], E[2, 0] - E[0, 2], E[0, 1] - E[1, 0]]) / 2 / dt
    Fx = F[:, lay.slice(block)] @ x
    scale = np.abs(F[:, lay.slice(block)]) @ np.abs(x)
    np.testing.assert_allclose(Fx[lay.slice("velocity")], dv_rate, rtol=0, atol=2e-3 * scale.max())
    np.testing.assert_allclose(Fx[lay.slice("misalignment")], psi_rate, rtol=0, atol=2e-3 * scale.max())
    assert np.abs(Fx[3:9]).max() > 0.2 * scale.max()  # the rows carry the coupling


# --- alignment at rest against TRIAD (non-level, non-north attitude, anisotropic sensors) ---

_ALIGN_LAYOUT = ins_error_layout(
    "position",
    "velocity",
    "misalignment",
    "gyro bias",
    "accel bias",
    "accel scale factor",
    "accel misalignment",
)


def _triad_psi(C_bn, lat, block, x, g=G0):
    """Oracle: the psi angle of an attitude found by TRIAD from faulty sensors at rest.

    The true sensors at rest are f^b = C_bn^T [0, 0, -g] and w^b = C_bn^T w_ie (Earth rate
    from pymap3d: the ECEF spin axis rotated into NED). TRIAD: the computed down axis is
    -f~/|f~| and north the horizontal part of w~ (a gyrocompass), east = down x north;
    C~_bn has these as rows. psi follows from C~_bn C_bn^T = I - [psi x]."""
    w_ie = np.array(pymap3d.ecef2nedv(0.0, 0.0, OMEGA_EARTH, lat, 0.3, deg=False))
    f_true, w_true = C_bn.T @ np.array([0.0, 0.0, -g]), C_bn.T @ w_ie
    f = _faulty_triad(f_true, block, x) if block.startswith("accel") else f_true
    w = _faulty_triad(w_true, block, x) if block.startswith("gyro") else w_true
    d = -f / np.linalg.norm(f)
    n = w - (w @ d) * d
    n /= np.linalg.norm(n)
    C_hat = np.vstack([n, np.cross(d, n), d])
    E = C_hat @ C_bn.T
    return np.array([E[1, 2] - E[2, 1], E[2, 0] - E[0, 2], E[0, 1] - E[1, 0]]) / 2


def _triad_T(C_bn, lat, layout):
    """psi per unit of each sensor state (central differences of `_triad_psi`; steps 1e-7
    for the accelerometer states, 1e-10 rad/s for gyro drift, small against the Earth rate)."""
    cols = []
    for b in layout.blocks:
        if not b.name.startswith(("gyro", "accel")):
            continue
        step = 1e-10 if b.name.startswith("gyro") else 1e-7
        for e in np.eye(3):
            plus, minus = _triad_psi(C_bn, lat, b.name, step * e), _triad_psi(C_bn, lat, b.name, -step * e)
            cols.append((plus - minus) / (2 * step))
    return np.column_stack(cols)


def test_gyrocompass_alignment_matches_triad():
    """Oracle: TRIAD alignment (`_triad_psi`) of an IMU at rest at 40 deg latitude with a
    non-level, non-north attitude, for each accelerometer bias, scale factor and
    misalignment axis and each gyro drift axis. With unit sensor variances in P0 the
    aligned covariance's psi-sensor block is the TRIAD sensitivity T, its psi block T T^T,
    and the other blocks are those of P0."""
    lay, lat = _ALIGN_LAYOUT, 40 * DEG
    C = fr_dcm(0.3, -0.2, 2.0)
    P0 = np.diag(np.arange(1.0, lay.size + 1.0))
    a = lay.slice("misalignment")
    s = np.arange(a.stop, lay.size)
    P0[np.ix_(s, s)] = np.eye(s.size)
    P = gyrocompass_alignment(P0, lay, lat=lat, C_bn=C)
    T = _triad_T(C, lat, lay)
    np.testing.assert_allclose(P[a][:, s], T, rtol=1e-6, atol=1e-9 * np.abs(T).max())
    np.testing.assert_allclose(P[a, a], T @ T.T, rtol=1e-6, atol=1e-9 * np.abs(T @ T.T).max())
    keep = np.r_[0 : a.start, s]
    np.testing.assert_array_equal(P[np.ix_(keep, keep)], P0[np.ix_(keep, keep)])


def test_levelling_alignment_matches_triad_tilt():
    """Oracle: the tilt of TRIAD (`_triad_psi`, rows north and east: they depend only on the
    computed down axis) for the accelerometer states; the heading is external: independent
    of the sensors, variance heading_sigma^2, and the tilt noise adds to the tilt variances."""
    lay, lat = _ALIGN_LAYOUT, 40 * DEG
    C = fr_dcm(0.3, -0.2, 2.0)
    P0 = np.eye(lay.size)
    a = lay.slice("misalignment")
    s = np.arange(a.stop, lay.size)
    P = levelling_alignment(P0, lay, heading_sigma=0.02, lat=lat, C_bn=C, tilt_noise_sigma=3e-4)
    T = _triad_T(C, lat, lay)[:2]
    T[:, :3] = 0.0  # gyro drift does not tilt a levelled platform
    np.testing.assert_allclose(P[a.start : a.start + 2][:, s], T, rtol=1e-6, atol=1e-9 * np.abs(T).max())
    np.testing.assert_allclose(P[a.start + 2, s], 0.0, atol=0)
    expect = np.zeros((3, 3))
    expect[:2, :2] = T @ T.T + 3e-4**2 * np.eye(2)
    expect[2, 2] = 0.02**2
    np.testing.assert_allclose(P[a, a], expect, rtol=1e-6, atol=1e-12)
    with pytest.raises(ValueError, match="heading_sigma"):
        levelling_alignment(P0, lay, heading_sigma=-1.0, lat=0.0)


def _frame_rate_from_pymap3d(lat, lon, h, v_ned, ell=None, half=10.0):
    """Oracle: the angular velocity of the local NED axes w.r.t. the Earth (resolved in NED)
    of a point moving in a straight line at v_ned through (lat, lon, h): pymap3d gives the
    geodetic position, hence the NED axes, at t = -half and +half; [w x] = C_ne^T dC_ne/dt
    by central differences."""
    r0 = np.array(pymap3d.geodetic2ecef(lat, lon, h, ell=ell, deg=False))

    def c_ne(r):
        la, lo, _ = pymap3d.ecef2geodetic(*r, ell=ell, deg=False)
        cols = [
            pymap3d.enu2uvw(0.0, 1.0, 0.0, la, lo, deg=False),
            pymap3d.enu2uvw(1.0, 0.0, 0.0, la, lo, deg=False),
        ]
        cols.append(-np.array(pymap3d.enu2uvw(0.0, 0.0, 1.0, la, lo, deg=False)))
        return np.column_stack(cols)

    M0 = c_ne(r0)
    v_e = M0 @ np.asarray(v_ned, float)
    W = M0.T @ (c_ne(r0 + half * v_e) - c_ne(r0 - half * v_e)) / (2 * half)
    return np.array([W[2, 1], W[0, 2], W[1, 0]])


@pytest.mark.parametrize("lat_deg", [-35.0, 0.0, 50.0])
def test_earth_and_transport_rates_against_pymap3d(lat_deg):
    """Oracles: pymap3d. The Earth rate in NED is the ECEF spin axis (0, 0, Omega) rotated
    into the local axes (ecef2nedv); the transport rate is the turning rate of the local
    axes of a point moving over a sphere of the Schuler radius (`_frame_rate_from_pymap3d`
    with a spherical pymap3d ellipsoid; the error model's spherical form), or over the
    WGS-84 ellipsoid (the strapdown's form), for a velocity with north, east and down parts."""
    from navcore.inertial import error_dynamics as ed

    lat, h = lat_deg * DEG, 5000.0
    expect = np.array(pymap3d.ecef2nedv(0.0, 0.0, OMEGA_EARTH, lat, 1.0, deg=False))
    np.testing.assert_allclose(earth_rate_ned(lat), expect, rtol=0, atol=1e-18)
    lats = np.array([lat, 0.3])
    batch = np.array([pymap3d.ecef2nedv(0.0, 0.0, OMEGA_EARTH, la, 1.0, deg=False) for la in lats])
    np.testing.assert_allclose(earth_rate_ned(lats), batch, rtol=0, atol=1e-18)
    sphere = pymap3d.Ellipsoid(WGS84_A, WGS84_A)
    v = np.array([120.0, -210.0, 15.0])
    w_en = _frame_rate_from_pymap3d(lat, 0.4, h, v, ell=sphere)
    np.testing.assert_allclose(ed.transport_rate_ned(v, lat, h), w_en, rtol=1e-7, atol=2e-12)
    # the strapdown's versions: WGS-84 ellipsoid (meridian and transverse radii)
    from navcore.inertial import strapdown as sd

    np.testing.assert_allclose(sd.earth_rate_ned(lat), expect, rtol=0, atol=1e-18)
    np.testing.assert_allclose(sd.earth_rate_ned(lats), batch, rtol=0, atol=1e-18)
    w_wgs = _frame_rate_from_pymap3d(lat, 0.4, h, v)
    np.testing.assert_allclose(sd.transport_rate_ned(v, lat, h), w_wgs, rtol=1e-7, atol=2e-12)
    # at the default height 0, moving north on the sphere of radius a turns the local axes
    # at v / a about west: (0, -v/a, 0) (closed form, tight enough to see a 1 m height)
    np.testing.assert_allclose(
        ed.transport_rate_ned([100.0, 0.0, 0.0], lat), [0.0, -100.0 / WGS84_A, 0.0], rtol=1e-14
    )
    vs = np.stack([v, -0.5 * v])
    np.testing.assert_allclose(
        ed.transport_rate_ned(vs, np.array([lat, lat]), np.array([h, h])),
        np.stack([w_en, -0.5 * w_en]),
        rtol=1e-7,
        atol=2e-12,
    )


def test_rest_eigenvalues_are_schuler_foucault_and_earth_rate():
    """Oracle: closed forms at rest at latitude L. The horizontal channels obey
    r'' + 2 Omega sin L (k x r') + ws^2 r = 0 (Schuler pendulum turned by the Coriolis force,
    Foucault), whose frequencies are sqrt(ws^2 + Oz^2) -+ Oz with Oz = Omega sin L; the psi
    angle is fixed in inertial space, so it turns at Omega in the navigation frame (0, +-j
    Omega); the frozen vertical adds two zeros. At the pole the free vertical channel has the
    real pair +-sqrt(2) ws (the unstable vertical of a gravity falling off as 1/r^2)."""
    ws = np.sqrt(G0 / WGS84_A)
    for lat in (50 * DEG, -20 * DEG):
        F = error_dynamics(
            CORE, f_ned=(0, 0, -G0), C_bn=fr_dcm(0.3, -0.2, 2.0), lat=lat, vertical_channel=False
        )
        ev = np.linalg.eigvals(F)
        oz = OMEGA_EARTH * np.sin(lat)
        f1, f2 = np.hypot(ws, oz) + abs(oz), np.hypot(ws, oz) - abs(oz)
        expect = np.sort([f1, -f1, f2, -f2, OMEGA_EARTH, -OMEGA_EARTH, 0.0, 0.0, 0.0])
        np.testing.assert_allclose(np.sort(ev.imag), expect, rtol=0, atol=1e-12)
        np.testing.assert_allclose(ev.real, 0.0, atol=1e-12)
    F = error_dynamics(CORE, f_ned=(0, 0, -G0), C_bn=np.eye(3), lat=np.pi / 2, vertical_channel=True)
    ev = np.linalg.eigvals(F)
    np.testing.assert_allclose(
        np.sort(ev.real), np.sort([-np.sqrt(2) * ws, np.sqrt(2) * ws] + [0.0] * 7), atol=1e-12
    )
    f1, f2 = np.hypot(ws, OMEGA_EARTH) + OMEGA_EARTH, np.hypot(ws, OMEGA_EARTH) - OMEGA_EARTH
    expect = np.sort([f1, -f1, f2, -f2, OMEGA_EARTH, -OMEGA_EARTH, 0.0, 0.0, 0.0])
    np.testing.assert_allclose(np.sort(ev.imag), expect, rtol=0, atol=1e-12)


def test_psi_turns_at_the_navigation_frame_rate_when_moving():
    """Oracle: with perfect gyros the computed frame's error psi is fixed in inertial space,
    so in the navigation frame it turns at |w_ie + w_en|; flying north at v over a sphere of
    radius R + h, w_en = (0, -v/(R+h), 0) is perpendicular to w_ie: the rate is
    sqrt(Omega^2 + (v/(R+h))^2) (and the psi block has eigenvalues 0, +-j of that)."""
    v, h, lat = 250.0, 8000.0, 35 * DEG
    F = error_dynamics(CORE, f_ned=(0, 0, -G0), C_bn=np.eye(3), v_ned=(v, 0.0, 0.0), lat=lat, h=h)
    a = CORE.slice("misalignment")
    ev = np.linalg.eigvals(F[a, a])
    rate = np.hypot(OMEGA_EARTH, v / (WGS84_A + h))
    np.testing.assert_allclose(np.sort(ev.imag), [-rate, 0.0, rate], rtol=0, atol=1e-15)
    np.testing.assert_allclose(ev.real, 0.0, atol=1e-15)


_AIDING = ins_error_layout(
    "position",
    "velocity",
    "misalignment",
    "gravity",
    "altimeter bias",
    "clock bias",
    "clock drift",
    "clock g-sensitivity",
)


def test_aiding_states_follow_closed_forms():
    """Oracles, closed forms propagated with scipy's matrix exponential (Van Loan for the
    noise): a constant gravity anomaly acts like an accelerometer bias in the Schuler loop,
    dr = dg / ws^2 (1 - cos ws t) per horizontal axis (equator, vertical frozen); the clock
    bias integrates drift plus the g-sensitive frequency error k |f| / g0; a Gauss-Markov
    state decays as exp(-beta t) with beta = speed / distance and, started at zero with the
    driving PSD, reaches sigma^2 (1 - exp(-2 beta t)); the clock bias variance is
    q_b t + q_d t^3 / 3 and the drift's q_d t (Brown & Hwang, two-state clock)."""
    lay = _AIDING
    ws, t = np.sqrt(G0 / WGS84_A), 900.0
    f = np.array([3.0, -4.0, -G0])
    F0 = error_dynamics(lay, f_ned=f, C_bn=np.eye(3), lat=0.0, vertical_channel=False)
    x0 = np.zeros(lay.size)
    dg = np.array([2e-4, -3e-4, 5e-4])
    x0[lay.slice("gravity")] = dg
    b0, d0, k = 3.0, 0.2, 0.05
    x0[lay.index("clock bias")], x0[lay.index("clock drift")], x0[lay.index("clock g-sensitivity")] = (
        b0,
        d0,
        k,
    )
    x = scipy.linalg.expm(F0 * t) @ x0
    np.testing.assert_allclose(x[:2], dg[:2] / ws**2 * (1 - np.cos(ws * t)), rtol=1e-9)
    assert x[2] == 0.0  # vertical frozen
    g_load = np.linalg.norm(f) / G0
    assert x[lay.index("clock bias")] == pytest.approx(b0 + d0 * t + k * g_load * t, rel=1e-12)
    # Gauss-Markov states moving at 200 m/s, and the process noise
    speed = 200.0
    src = ErrorSources(
        imu=ImuSpec("none"),
        gravity=GaussMarkov(30 * MICRO_G, 40_000.0),
        altimeter=GaussMarkov(25.0, 9_000.0),
        clock=ClockModel(bias_sigma=10.0, drift_sigma=0.1, bias_psd=0.04, drift_psd=0.009),
    )
    F = error_dynamics(lay, f_ned=f, C_bn=np.eye(3), v_ned=(0.0, speed, 0.0), lat=0.0, sources=src)
    Q = process_noise_psd(lay, src, speed_mps=speed)
    t = 60.0
    Phi, Qd = van_loan_expm(F, Q, t)
    alt, grav = lay.index("altimeter bias"), lay.slice("gravity")
    beta_a, beta_g = speed / 9_000.0, speed / 40_000.0
    assert Phi[alt, alt] == pytest.approx(np.exp(-beta_a * t), rel=1e-10)
    np.testing.assert_allclose(np.diag(Phi[grav, grav]), np.exp(-beta_g * t), rtol=1e-10)
    assert Qd[alt, alt] == pytest.approx(25.0**2 * (1 - np.exp(-2 * beta_a * t)), rel=1e-10)
    np.testing.assert_allclose(
        np.diag(Qd[grav, grav]), (30 * MICRO_G) ** 2 * (1 - np.exp(-2 * beta_g * t)), rtol=1e-10
    )
    cb, cd = lay.index("clock bias"), lay.index("clock drift")
    assert Qd[cb, cb] == pytest.approx(0.04 * t + 0.009 * t**3 / 3, rel=1e-10)
    assert Qd[cd, cd] == pytest.approx(0.009 * t, rel=1e-10)


def test_initial_covariance_places_each_sigma_in_its_block():
    """Oracle: the documented meaning of each block (module table): every source's 1-sigma,
    given distinct values, appears squared on the diagonal of its own block only."""
    lay = ins_error_layout(
        "position",
        "velocity",
        "misalignment",
        "gyro bias",
        "gyro scale factor",
        "gyro misalignment",
        "accel bias",
        "accel scale factor",
        "accel misalignment",
        "gravity",
        "altimeter bias",
        "clock bias",
        "clock drift",
        "clock g-sensitivity",
        "pseudorange bias",
        "range-rate bias",
        "doppler bias",
        "doppler scale factor",
        "doppler misalignment",
        channels=2,
    )
    imu = ImuSpec(  # distinct values, within the plausible range of each source (x 1/100)
        "x",
        gyro_bias=0.01,
        gyro_scale_factor=0.02,
        gyro_misalignment=0.03,
        accel_bias=0.04,
        accel_scale_factor=0.05,
        accel_misalignment=0.06,
        gyro_random_walk=0.0099,
        accel_random_walk=0.098,
    )
    src = ErrorSources(
        imu=imu,
        gravity=GaussMarkov(7.0, 1e4),
        altimeter=GaussMarkov(8.0, 1e4),
        clock=ClockModel(bias_sigma=9.0, drift_sigma=10.0, g_sensitivity_sigma=11.0),
        pseudorange_bias_sigma=12.0,
        range_rate_bias_sigma=13.0,
        doppler_bias=(14.0, 15.0, 16.0),
        doppler_scale_factor=(17.0, 18.0, 19.0),
        doppler_misalignment=20.0,
    )
    P = initial_covariance(
        lay,
        src,
        position_sigma=(0.1, 0.2, 0.3),
        velocity_sigma=(0.4, 0.5, 0.6),
        attitude_sigma=(0.7, 0.8, 0.9),
    )
    expect = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, *[v / 100 for v in range(1, 7) for _ in range(3)]]
    expect += [7.0] * 3 + [8.0, 9.0, 10.0, 11.0, 12.0, 12.0, 13.0, 13.0, 14.0, 15.0, 16.0, 17.0, 18.0, 19.0]
    expect += [20.0] * 3
    np.testing.assert_array_equal(P, np.diag(np.array(expect) ** 2))
    # without the optional sources those blocks start at zero, and the white noises stay out
    P_bare = initial_covariance(lay, ErrorSources(imu=imu))
    for b in ("gravity", "altimeter bias", "clock bias", "clock drift", "clock g-sensitivity"):
        assert np.all(np.diag(P_bare)[lay.slice(b)] == 0.0), b


def test_skew_stack_is_the_cross_product():
    """Oracle: numpy.cross, for one vector and for a (2, 4, 3) batch."""
    rng = np.random.default_rng(5)
    a, b = rng.normal(size=(2, 2, 4, 3))
    np.testing.assert_allclose(
        np.einsum("nij,nj->ni", skew_stack(a[0]), b[0]), np.cross(a[0], b[0]), rtol=0, atol=1e-15
    )  # a (4, 3) batch
    np.testing.assert_allclose(
        np.einsum("...ij,...j->...i", skew_stack(a), b), np.cross(a, b), rtol=0, atol=1e-15
    )
    np.testing.assert_allclose(skew_stack(a[0, 0]) @ b[0, 0], np.cross(a[0, 0], b[0, 0]), rtol=0, atol=1e-15)


@pytest.mark.parametrize("lat_deg", [55.0, -30.0])
def test_moving_horizontal_eigenvalues_closed_form(lat_deg):
    """Oracle: the closed-form frequencies of the horizontal psi-angle error equations of a
    vehicle flying east at v (vertical frozen). In complex form z = dr_N + j dr_E,
    u = dv_N + j dv_E they read z' = u - j a z, u' = -ws^2 z - j b u, with a the down
    component of the transport rate (turning of the position error) and b that of
    2 w_ie + w_en (Coriolis); so s = j [-(a + b) +- sqrt((a - b)^2 + 4 ws^2)] / 2 and the
    conjugates, ws^2 = g / (R + h). The rates come from pymap3d (`_frame_rate_from_pymap3d`
    on the Schuler sphere, the ECEF spin axis in NED), not from navcore; their finite
    differences limit the agreement to about 1e-8 relative (a sign error in either rate moves
    the frequencies by about 4 %)."""
    lat, h, v = lat_deg * DEG, 8000.0, 240.0
    w_en = _frame_rate_from_pymap3d(lat, 0.2, h, [0.0, v, 0.0], ell=pymap3d.Ellipsoid(WGS84_A, WGS84_A))
    w_ie = np.array(pymap3d.ecef2nedv(0.0, 0.0, OMEGA_EARTH, lat, 0.2, deg=False))
    a, b = w_en[2], 2 * w_ie[2] + w_en[2]
    g = 9.78  # a local gravity other than the default
    ws2 = g / (WGS84_A + h)
    root = np.sqrt((a - b) ** 2 + 4 * ws2)
    lam = np.array([(-(a + b) + root) / 2, (-(a + b) - root) / 2])
    F = error_dynamics(
        CORE,
        f_ned=(0, 0, -G0),
        C_bn=np.eye(3),
        v_ned=(0.0, v, 0.0),
        lat=lat,
        h=h,
        g=g,
        vertical_channel=False,
    )
    idx = [0, 1, 3, 4]
    ev = np.linalg.eigvals(F[np.ix_(idx, idx)])
    np.testing.assert_allclose(np.sort(ev.imag), np.sort(np.r_[lam, -lam]), rtol=0, atol=1e-7 * np.sqrt(ws2))
    np.testing.assert_allclose(ev.real, 0.0, atol=1e-7 * np.sqrt(ws2))


def test_alignment_without_sensor_states_and_at_the_default_attitude():
    """Oracles: TRIAD (`_triad_T`) at the default level, north-pointing attitude; and, for a
    layout with no sensor states, the definitions: the gyrocompassed attitude carries no
    error, the levelled one only the external heading and the tilt noise, and the position
    and velocity blocks of P0 are kept."""
    lay, lat = _ALIGN_LAYOUT, 40 * DEG
    a = lay.slice("misalignment")
    s = np.arange(a.stop, lay.size)
    P = gyrocompass_alignment(np.eye(lay.size), lay, lat=lat)
    np.testing.assert_allclose(P[a][:, s], _triad_T(np.eye(3), lat, lay), rtol=1e-6, atol=1e-12)
    P0 = np.diag(np.arange(1.0, 10.0))
    P = gyrocompass_alignment(P0, CORE, lat=lat)
    np.testing.assert_array_equal(P, np.diag([1.0, 2, 3, 4, 5, 6, 0, 0, 0]))
    P = levelling_alignment(P0, CORE, heading_sigma=0.1, lat=lat, tilt_noise_sigma=0.01)
    np.testing.assert_allclose(P, np.diag([1.0, 2, 3, 4, 5, 6, 1e-4, 1e-4, 1e-2]), rtol=1e-15, atol=0)


def test_gauss_markov_noise_needs_motion_and_its_block():
    """Oracle: the definition of a distance-correlated process (SP Table 2.4): at rest
    (the default speed) its time constant is infinite and it is not driven; a source whose
    block is not in the layout adds nothing."""
    src = ErrorSources(imu=ImuSpec("n", accel_random_walk=0.01), gravity=GaussMarkov(1e-4, 1e4))
    lay = ins_error_layout("position", "velocity", "misalignment", "gravity")
    assert np.all(np.diag(process_noise_psd(lay, src))[lay.slice("gravity")] == 0.0)
    src = ErrorSources(
        imu=ImuSpec("n", accel_random_walk=0.01),
        gravity=GaussMarkov(1e-4, 1e4),
        altimeter=GaussMarkov(5.0, 1e4),
    )
    Q = process_noise_psd(CORE, src, speed_mps=100.0)
    np.testing.assert_array_equal(np.diag(Q), [0.0] * 3 + [1e-4] * 3 + [0.0] * 3)


def test_layout_sizes_units_and_name():
    """Oracle: the block table of the module documentation (sizes and units), the documented
    default of four receiver channels, and the layout's name as given."""
    lay = ins_error_layout(
        "position", "gyro bias", "altimeter bias", "clock drift", "pseudorange bias", name="L"
    )
    assert lay.name == "L" and ins_error_layout("position").name == ""
    assert [(b.name, b.size, b.unit) for b in lay.blocks] == [
        ("position", 3, "m"),
        ("gyro bias", 3, "rad/s"),
        ("altimeter bias", 1, "m"),
        ("clock drift", 1, "m/s"),
        ("pseudorange bias", 4, "m"),
    ]
    assert ins_error_layout("range-rate bias", channels=7).size == 7


def test_psi_sign_convention_against_a_strapdown_step_and_its_conversion():
    """Oracle: one short strapdown step (navcore.inertial.strapdown) started from the computed
    attitude C~_bn = exp(-[psi x]) C_bn (scipy rotation) with perfect sensors, against the true
    attitude: the velocity-error rate is F[v, psi] psi = -psi x f (the module's convention,
    C~ = (I - [psi x]) C). The opposite sign (C~ = (I + [psi x]) C, that of error_model17 and
    target_location) gives the negative rate; psi_to_attitude_error converts one into the other."""
    from scipy.spatial.transform import Rotation

    from navcore import frames as fr
    from navcore.inertial.error_dynamics import psi_to_attitude_error
    from navcore.inertial.strapdown import NavState, strapdown_step

    lay = ins_error_layout("position", "velocity", "misalignment")
    C = fr.dcm_from_euler(*_ATT)
    F = error_dynamics(lay, f_ned=C @ _F_B, C_bn=C, omega_ib_b=_W_B, lat=0.7)
    psi = np.array([2e-4, -3e-4, 5e-4])
    C_hat = Rotation.from_rotvec(-psi).as_matrix() @ C
    dt = 1e-5
    good = strapdown_step(
        NavState(np.zeros((1, 3)), np.zeros((1, 3)), fr.quat_from_dcm(C)[None]), _W_B[None], _F_B[None], dt
    )
    bad = strapdown_step(
        NavState(np.zeros((1, 3)), np.zeros((1, 3)), fr.quat_from_dcm(C_hat)[None]),
        _W_B[None],
        _F_B[None],
        dt,
    )
    dv_rate = (bad.vel[0] - good.vel[0]) / dt
    # agreement to second order in psi (5e-4 rad): 1e-3 of the largest component
    np.testing.assert_allclose(
        F[lay.slice("velocity"), lay.slice("misalignment")] @ psi,
        dv_rate,
        rtol=0,
        atol=1e-3 * np.abs(dv_rate).max(),
    )
    T = psi_to_attitude_error(lay)
    alpha = (T @ np.r_[np.zeros(6), psi])[lay.slice("misalignment")]
    np.testing.assert_allclose(Rotation.from_rotvec(alpha).as_matrix() @ C, C_hat, atol=1e-12)
    np.testing.assert_array_equal(T @ T, np.eye(lay.size))
    with pytest.raises(ValueError, match="misalignment"):
        psi_to_attitude_error(ins_error_layout("position", "velocity"))


def test_gravity_tuning_is_the_zero_frequency_psd_of_the_anomaly() -> None:
    """Oracle: the PSD at zero frequency of a stationary first-order Gauss-Markov process is the
    integral of its autocorrelation sigma^2 exp(-|t| / tau) over all lags (Wiener-Khinchin),
    taken by scipy.integrate.quad with tau = d / v out to 60 tau (the tail is e^-60); it lands on
    the velocity states only, and a missing anomaly or a vehicle at rest gives no tuning."""
    from scipy.integrate import quad

    lay = ins_error_layout("position", "velocity", "misalignment", "accel bias")
    sigma, d, v = 3e-4, 25_000.0, 180.0
    src = ErrorSources(ImuSpec("ideal"), gravity=GaussMarkov(sigma, d))
    tau = d / v
    psd0 = 2 * quad(lambda t: sigma**2 * np.exp(-t / tau), 0.0, 60 * tau, epsabs=0.0, epsrel=1e-12)[0]
    q = gravity_tuning_psd(lay, src, v)
    np.testing.assert_allclose(q[lay.slice("velocity")], psd0, rtol=1e-9)
    assert not q[: lay.slice("velocity").start].any() and not q[lay.slice("velocity").stop :].any()
    assert not gravity_tuning_psd(lay, src, 0.0).any()
    assert not gravity_tuning_psd(lay, ErrorSources(ImuSpec("ideal")), v).any()
    with pytest.raises(ValueError, match="speed_mps"):
        gravity_tuning_psd(lay, src, -1.0)
