"""Tests of the jammer-geometry model (navcore.gnss.jammer_geometry) and the SP flyby scenario."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

from navcore.gnss import jammer_geometry as jg
from navcore.gnss.antijam import js_for_effective_cn0
from navcore.integration.geometry import lock_table
from navcore.units import GPS_L1_WAVELENGTH_M, GPS_P_CHIP_RATE_HZ

N0 = -204.0
RC = GPS_P_CHIP_RATE_HZ
LAM = GPS_L1_WAVELENGTH_M


@pytest.mark.parametrize("q", [2.0, 1.3])
def test_effective_cn0_in_watts(q):
    """Oracle: the law in linear units, C / (N0 + J / (Q Rc)) with C, J in W and N0 in W/Hz
    (Kaplan Sec. 6.3), on a (7, 3) broadcast of jammer and carrier powers."""
    C = np.array([-163.0, -160.0, -158.0])
    J = np.linspace(-150.0, -90.0, 7)[:, None]
    ours = jg.effective_cn0_with_jammer_dbhz(C, J, N0, RC, q)
    c_w, j_w, n0_w = 10 ** (C / 10), 10 ** (J / 10), 10 ** (N0 / 10)
    np.testing.assert_allclose(ours, 10 * np.log10(c_w / (n0_w + j_w / (q * RC))), atol=1e-9)
    assert ours.shape == (7, 3)


def test_received_power_and_threshold_range_friis():
    """Oracle: Friis in watts, P_r = ERP G_r (lambda / 4 pi d)^2, and the distance at which it
    equals a given power solved from it by hand, with a -10 dBi receive gain."""
    erp_dbw, g_db = 40.0, -10.0
    d = np.array([500.0, 12_000.0, 3e5])
    p_w = 10 ** (erp_dbw / 10) * 10 ** (g_db / 10) * (LAM / (4 * np.pi * d)) ** 2
    np.testing.assert_allclose(
        jg.received_jammer_power_dbw(erp_dbw, d, LAM, g_db), 10 * np.log10(p_w), atol=1e-10
    )
    np.testing.assert_allclose(jg.free_space_loss_db(d, LAM), -10 * np.log10((LAM / (4 * np.pi * d)) ** 2))
    target_w = 1e-11
    d_star = LAM / (4 * np.pi) * np.sqrt(10 ** ((erp_dbw + g_db) / 10) / target_w)
    assert jg.threshold_range_m(erp_dbw, -110.0, LAM, g_db) == pytest.approx(d_star, rel=1e-12)


def test_threshold_jammer_power_matches_antijam_js():
    """Oracle: js_for_effective_cn0 (J/S at the threshold) plus the carrier power gives J*,
    and J* fed back into the effective C/N0 gives the threshold."""
    C = -161.0
    for gamma in (18.0, 21.0, 30.0):
        js = js_for_effective_cn0(C - N0, gamma, RC, 2.0)
        jstar = jg.jammer_power_at_threshold_dbw(C, gamma, N0, RC, 2.0)
        assert jstar == pytest.approx(C + js, abs=1e-9)
        assert jg.effective_cn0_with_jammer_dbhz(C, jstar, N0, RC, 2.0) == pytest.approx(gamma, abs=1e-9)


def test_straight_track_crossings_closed_form_against_grid():
    """Oracle: the quadratic d_min^2 + v^2 (t - t_ca)^2 = d*^2 (closed form) against a 0.05-s
    grid of the effective C/N0 with the vectorised hysteresis; crossings agree within a step."""
    erp, v, dmin, tca = 40.0, 200.0, 12_000.0, 1500.0
    C = np.array([-160.0, -163.0])
    t = np.arange(0.0, 3000.0, 0.05)
    d = jg.straight_track_range_m(t, v, dmin, tca)
    J = jg.received_jammer_power_dbw(erp, d, LAM, -10.0)
    cn0 = jg.effective_cn0_with_jammer_dbhz(C, J[:, None], N0, RC)
    locked = jg.hysteresis_lock(cn0, 18.0, 21.0)
    for c in range(2):
        r_in = jg.threshold_range_m(erp, jg.jammer_power_at_threshold_dbw(C[c], 18.0, N0, RC), LAM, -10.0)
        r_out = jg.threshold_range_m(erp, jg.jammer_power_at_threshold_dbw(C[c], 21.0, N0, RC), LAM, -10.0)
        t_in, _ = jg.straight_track_crossing_times(r_in, dmin, v, tca)
        _, t_out = jg.straight_track_crossing_times(r_out, dmin, v, tca)
        iv = jg.outage_intervals(t, locked[:, c])
        assert len(iv) == 1
        assert iv[0][0] == pytest.approx(t_in, abs=0.05)
        assert iv[0][1] == pytest.approx(t_out, abs=0.05)
    # the stronger satellite (index 0) is lost later and back earlier
    iv0, iv1 = (jg.outage_intervals(t, locked[:, c])[0] for c in range(2))
    assert iv0[0] > iv1[0] and iv0[1] < iv1[1]


def test_crossing_nan_when_track_stays_outside():
    """Closed form: no real root when the threshold range is below the closest approach."""
    t_in, t_out = jg.straight_track_crossing_times(5000.0, 8000.0, 100.0)
    assert np.isnan(t_in) and np.isnan(t_out)
    t_in, t_out = jg.straight_track_crossing_times(10_000.0, 8000.0, 100.0, 50.0)
    assert (t_in, t_out) == pytest.approx((50.0 - 60.0, 50.0 + 60.0))


def test_range_closed_form():
    """Pythagoras: 3-4-5 triangle, and slant_range_m against the same geometry in NED."""
    assert jg.straight_track_range_m(10.0, 300.0, 4000.0) == pytest.approx(5000.0)
    pos = np.array([[0.0, 0.0, -7000.0], [3000.0, 0.0, -7000.0]])
    r = jg.slant_range_m(pos, np.array([0.0, 4000.0, 0.0]))
    np.testing.assert_allclose(r, [np.hypot(4000.0, 7000.0), np.sqrt(3000.0**2 + 4000.0**2 + 7000.0**2)])


def test_effective_cn0_monotone_in_range_and_power():
    """Monotonicity: C/N0 rises with range and falls with jammer power; it tends to the
    unjammed C - N0 far away."""
    d = np.geomspace(1e3, 1e8, 200)
    c1 = jg.effective_cn0_with_jammer_dbhz(-163.0, jg.received_jammer_power_dbw(30.0, d, LAM), N0, RC)
    c2 = jg.effective_cn0_with_jammer_dbhz(-163.0, jg.received_jammer_power_dbw(40.0, d, LAM), N0, RC)
    assert np.all(np.diff(c1) > 0)
    assert np.all(c2 < c1)
    assert c1[-1] == pytest.approx(-163.0 - N0, abs=1e-2)


def test_pll_jitter_threshold_root():
    """Oracle: brentq on k * sigma_phi(C/N0) = phi_max with the jitter formula evaluated directly."""
    for bn in (0.225, 0.64, 5.83, 15.0):
        x = 10 ** (jg.pll_jitter_threshold_dbhz(bn, 90.0, 3.0, 0.02) / 10)

        def f(c, bn=bn):
            return 3.0 * np.degrees(np.sqrt(bn / c * (1 + 1 / (2 * 0.02 * c)))) - 90.0

        assert x == pytest.approx(brentq(f, 1e-3, 1e6, xtol=1e-12), rel=1e-9)
    assert jg.carrier_loss_threshold_dbhz(5.83, 19.0, 90.0) == 19.0
    assert jg.carrier_loss_threshold_dbhz(5.83, 10.0) == pytest.approx(jg.pll_jitter_threshold_dbhz(5.83))


def _unambiguous_range_deg(discriminator) -> float:
    """Width (deg) of the phase interval around 0 on which a simulated discriminator returns
    the true phase error, with random data bits (seed 4) flipping the sign of I and Q."""
    rng = np.random.default_rng(4)
    phi = np.radians(np.arange(-179.5, 180.0, 1.0))
    bits = rng.choice([-1.0, 1.0], size=phi.size)
    out = discriminator(bits * np.sin(phi), bits * np.cos(phi))
    good = np.abs(out - phi) < 1e-9
    return float(np.degrees(phi[good].max() - phi[good].min()) + 1.0)


def test_costas_and_pll_thresholds_follow_their_discriminators():
    """Oracles: (i) simulated discriminators on data-modulated I/Q: the Costas atan(Q/I) is
    unambiguous over 180 deg whatever the data bit, so its rule of thumb (3 sigma <= a quarter
    of the pull-in range, Kaplan Sec. 5.6.2) is 45 deg, while atan2(Q, I) (a pure PLL, 360 deg)
    is wrong whenever the bit is -1, so it needs a data-free signal; (ii) brentq on the jitter
    formula at 45 and 90 deg. The old default was the pure-PLL 90 deg (15.6 dB-Hz at 5.83 Hz)
    for data-modulated C/A; the Costas threshold is 20.2 dB-Hz."""
    costas = _unambiguous_range_deg(lambda q, i: np.arctan(q / i))
    assert costas == pytest.approx(180.0)
    assert jg.LOOP_PHASE_LIMIT_DEG["costas"] == costas / 4
    assert jg.LOOP_PHASE_LIMIT_DEG["pll"] == 360.0 / 4
    rng = np.random.default_rng(5)
    phi = rng.uniform(-np.pi, np.pi, 100)
    bits = -np.ones(100)
    assert not np.allclose(np.arctan2(bits * np.sin(phi), bits * np.cos(phi)), phi)  # PLL fooled by data

    def root(limit_deg, bn=5.83):
        return 10 * np.log10(
            brentq(
                lambda c: 3.0 * np.degrees(np.sqrt(bn / c * (1 + 1 / (2 * 0.02 * c)))) - limit_deg,
                1e-3,
                1e6,
                xtol=1e-12,
            )
        )

    assert jg.pll_jitter_threshold_dbhz(5.83) == pytest.approx(root(45.0), abs=1e-9)
    assert jg.pll_jitter_threshold_dbhz(5.83, loop="costas") == pytest.approx(root(45.0), abs=1e-9)
    assert jg.pll_jitter_threshold_dbhz(5.83, loop="pll") == pytest.approx(root(90.0), abs=1e-9)
    assert jg.carrier_loss_threshold_dbhz(5.83, 19.0) == pytest.approx(
        root(45.0), abs=1e-9
    )  # above the floor
    assert jg.carrier_loss_threshold_dbhz(5.83, 19.0, loop="pll") == 19.0
    # an explicit (printed) limit overrides the loop's rule
    assert jg.pll_jitter_threshold_dbhz(5.83, 90.0) == pytest.approx(root(90.0), abs=1e-9)
    with pytest.raises(ValueError, match="loop"):
        jg.pll_jitter_threshold_dbhz(5.83, loop="fll")


def _loop_hysteresis(c, lo, hi, initially_locked=True):
    """Brute-force state machine, one sample and one channel at a time."""
    lo, hi = np.broadcast_to(lo, c.shape[1:]), np.broadcast_to(hi, c.shape[1:])
    out = np.empty(c.shape, dtype=bool)
    for j in range(c.shape[1]):
        state = initially_locked
        for k in range(c.shape[0]):
            if c[k, j] < lo[j]:
                state = False
            elif c[k, j] >= hi[j]:
                state = True
            out[k, j] = state
    return out


@pytest.mark.parametrize("initially_locked", [True, False])
def test_hysteresis_matches_state_machine(initially_locked):
    """Oracle: a sample-by-sample state machine on seeded random C/N0 histories that start
    between the thresholds, with common and with per-channel thresholds."""
    rng = np.random.default_rng(5)
    c = 19.5 + np.cumsum(rng.normal(0, 1.0, (400, 6)), axis=0) * 0.3
    got = jg.hysteresis_lock(c, 18.0, 21.0, initially_locked=initially_locked)
    np.testing.assert_array_equal(got, _loop_hysteresis(c, 18.0, 21.0, initially_locked))
    lo, hi = np.array([17.0, 18.0, 18.5, 19.0, 19.4, 19.0]), np.array([20.0, 21.0, 19.6, 22.0, 19.6, 19.0])
    got = jg.hysteresis_lock(c, lo, hi, initially_locked=initially_locked)
    np.testing.assert_array_equal(got, _loop_hysteresis(c, lo, hi, initially_locked))


def test_carrier_loss_threshold_passes_its_loop_parameters():
    """Oracle: brentq on k sigma_phi(C/N0) = phi_max with the jitter formula (Kaplan Sec. 5.6.2)
    at k = 2.5, T = 10 ms and a 60-deg limit, for an array of bandwidths, against the floor."""

    def root(bn, limit_deg=60.0, k=2.5, t=0.01):
        f = lambda c: k * np.degrees(np.sqrt(bn / c * (1 + 1 / (2 * t * c)))) - limit_deg
        return 10 * np.log10(brentq(f, 1e-3, 1e6, xtol=1e-12))

    bns = np.array([2.0, 10.0, 18.0])
    got = jg.carrier_loss_threshold_dbhz(bns, 16.0, 60.0, 2.5, 0.01, loop="pll")
    expected = np.maximum(16.0, [root(b) for b in bns])
    np.testing.assert_allclose(got, expected, atol=1e-9)
    assert expected[0] == 16.0 and expected[2] > 16.0
    np.testing.assert_allclose(
        jg.pll_jitter_threshold_dbhz(bns, k_sigma=2.5, coherent_s=0.01, loop="pll"),
        [root(b, 90.0) for b in bns],
        atol=1e-9,
    )


def test_constant_js_limit_is_the_all_satellites_outage():
    """Constant-J/S limit: a J/S held above every loss threshold from t1 and dropped below the
    reacquisition thresholds at t2 gives the same lock table as the engine's event list with
    all satellites lost at t1 and back at t2 (the head-on approach's kind of outage)."""
    t = np.arange(0.0, 600.0, 1.0)
    C = np.array([-163.0, -161.0, -160.0, -158.0])
    J = np.where((t >= 120.0) & (t < 420.0), -80.0, -200.0)
    cn0 = jg.effective_cn0_with_jammer_dbhz(C, J[:, None], N0, RC)
    code = jg.hysteresis_lock(cn0, 18.0, 21.0)
    ev = [(120.0, c, "code", False) for c in range(4)] + [(420.0, c, "code", True) for c in range(4)]
    ref, _ = lock_table(t, 4, ev)
    np.testing.assert_array_equal(code, ref)
    avail_tc = jg.outage_intervals(t, code.sum(1) >= 1)
    avail_lc = jg.outage_intervals(t, code.sum(1) >= 4)
    assert avail_tc == avail_lc == [(120.0, 420.0)]


def test_outage_intervals_edges():
    t = np.arange(6.0)
    assert jg.outage_intervals(t, [True, False, False, True, False, False]) == [(1.0, 3.0), (4.0, 5.0)]
    assert jg.outage_intervals(t, np.ones(6, bool)) == []
    assert jg.outage_intervals(t, [False, True, True, False, True, True]) == [(0.0, 1.0), (3.0, 4.0)]
    assert jg.outage_intervals(t, np.zeros(6, bool)) == [(0.0, 5.0)]


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: jg.straight_track_range_m(0.0, -1.0, 10.0), "speed_mps"),
        (lambda: jg.straight_track_range_m(0.0, 1.0, -10.0), "closest_range_m"),
        (lambda: jg.free_space_loss_db(0.0, LAM), "range_m"),
        (lambda: jg.free_space_loss_db(1.0, 0.0), "wavelength_m"),
        (lambda: jg.jammer_power_at_threshold_dbw(-163.0, 45.0, N0, RC), "threshold_dbhz"),
        (lambda: jg.effective_cn0_with_jammer_dbhz(-163.0, -100.0, N0, RC, q=0.0), "q"),
        (lambda: jg.hysteresis_lock(np.zeros(5), 18.0, 21.0), "cn0_dbhz"),
        (lambda: jg.hysteresis_lock(np.zeros((5, 1)), 21.0, 18.0), "reacquisition_dbhz"),
        (lambda: jg.LockThresholds(18.0, 19.0, 17.0, 22.0), "code_reacquisition"),
        (lambda: jg.pll_jitter_threshold_dbhz(-1.0), "noise_bandwidth_hz"),
        (lambda: jg.outage_intervals(np.arange(3.0), [True]), "available"),
    ],
)
def test_bad_input_names_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_flyby_calibration_and_flat_antenna_limit():
    """Scenario: the fitted jammer gives the 20-min loosely coupled blackout (lock tables on the
    1-s grid), and with a flat antenna (no gain drop towards the horizon: every satellite at the
    same C/N0) the four codes the loosely coupled receiver needs and the one the tightly coupled
    filter needs go and come back together: the two blackouts coincide."""
    from navcore.claims.inputs import overriding, recording
    from navcore.papers import sp_flyby as fb
    from navcore.papers import sp_scenario_wiring as sc

    lc, tc = sc.SYSTEMS[0], sc.SYSTEMS[2]
    with recording():
        s, e = fb._outage(lc, fb.locks(lc, fb.calibrated_jammer_db()).code)
        assert (e - s) / 60.0 == pytest.approx(20.0, abs=1.0 / 60.0)
        with overriding({"SP.flyby.antenna_gain_drop_db": 0.0}):
            x = fb.calibrated_jammer_db()
            b_lc = fb._outage(lc, fb.locks(lc, x).code)
            b_tc = fb._outage(tc, fb.locks(tc, x).code)
    assert b_lc == b_tc


def test_flyby_table_2_7_counts_by_hand():
    """Oracle: the cell count of every reacquired satellite recomputed by hand from the run's
    covariance snapshot before that satellite's first pseudorange, ceil(2 sigma / 30 m) with
    sigma^2 = u^T P_position u (Sec. 2.5, the range uncertainty along the line of sight), and
    the range-rate sigma from the velocity block."""
    from navcore.claims.inputs import recording
    from navcore.papers import sp_flyby as fb

    with recording():
        runs = {s.label: r for s, r in fb.flyby_runs().items()}
        search = fb.reacquisition_search()
        u_all = fb.flyby_geometry().u_ned
    for label, v in search.items():
        r = runs[label]
        p, vel = r.truth_layout.slice("position"), r.truth_layout.slice("velocity")
        assert len(v["prn"]) == 7
        for c, k, cells, srr in zip(
            v["channel"], v["step"], v["range_cells"], v["sigma_range_rate_mps"], strict=True
        ):
            P = r.snapshots[k - 1]
            u = u_all[k, c]
            sigma = np.sqrt(u @ P[p, p] @ u)
            assert cells == max(1, int(np.ceil(2 * sigma / 30.0)))
            assert srr == pytest.approx(np.sqrt(u @ P[vel, vel] @ u), rel=1e-12)


def test_dynamic_error_bound_against_a_fine_simulation():
    """Oracle: scipy.signal.lsim of the third-order loop's error transfer function
    s^3 / (s^3 + 2 w s^2 + 2 w^2 s + w^3) (the loop of SP Sec. 2.5) driven by the phase
    (double integral) of a piecewise-constant acceleration history, on a 1-ms grid: the bound
    is never below the simulated error at any time of its interval and equals the peak after
    an isolated step."""
    from scipy import signal

    from navcore.gnss.tracking import third_order_loop_dynamic_error_bound

    w, dt = 1.3, 1.0
    a = np.zeros(40)
    a[5:12] = 2.0  # a 2 m/s^2 acceleration on for 7 s
    a[20:] = -1.0
    bound = third_order_loop_dynamic_error_bound(a, dt, w)
    fine = np.arange(0.0, 40.0, 1e-3)
    acc = a[np.minimum((fine // dt).astype(int), a.size - 1)]
    # the loop error for a phase input theta'' = acc: E(s) = s^3/D(s) * Acc(s)/s^2 = s/D(s) Acc(s)
    _, err, _ = signal.lsim(signal.lti([1.0, 0.0], [1.0, 2 * w, 2 * w**2, w**3]), acc, fine)
    per_sample = np.array([np.abs(err[(fine >= k * dt) & (fine < (k + 1) * dt)]).max() for k in range(40)])
    assert np.all(bound >= per_sample - 1e-6)
    # after the first step alone (samples 5-11) the bound is the simulated error
    np.testing.assert_allclose(bound[5:12], per_sample[5:12], rtol=2e-3)


def test_jitters_and_jammed_cn0_against_their_formulas():
    """Oracles: Kaplan & Hegarty's thermal jitter formulas written out (PLL: Bn/(C/N0)
    (1 + 1/(2 T C/N0)) rad^2; noncoherent early-minus-late DLL: Bn d/(2 C/N0)
    (1 + 2/(T C/N0 (2 - d))) chips^2) and the effective C/N0 law in watts,
    C / (N0 + J/(Q Rc)), with J/(Q Rc N0) the jammer-to-noise ratio."""
    c = 10 ** (np.array([15.0, 25.0, 40.0]) / 10)
    np.testing.assert_allclose(
        jg.pll_thermal_jitter_deg([15.0, 25.0, 40.0], 0.3, 0.02),
        np.degrees(np.sqrt(0.3 / c * (1 + 1 / (2 * 0.02 * c)))),
        rtol=1e-12,
    )
    np.testing.assert_allclose(
        jg.dll_thermal_jitter_chips([15.0, 25.0, 40.0], 1.5, 0.8, 0.02),
        np.sqrt(1.5 * 0.8 / (2 * c) * (1 + 2 / (0.02 * c * 1.2))),
        rtol=1e-12,
    )
    j_w, n0_w, c_w = 10 ** (-120 / 10), 10 ** (N0 / 10), 10 ** (-160 / 10)
    jn_db = 10 * np.log10(j_w / (2.0 * RC * n0_w))
    assert jg.jammed_cn0_dbhz(10 * np.log10(c_w / n0_w), jn_db) == pytest.approx(
        10 * np.log10(c_w / (n0_w + j_w / (2.0 * RC))), abs=1e-10
    )
    with pytest.raises(ValueError, match="spacing_chips"):
        jg.dll_thermal_jitter_chips(30.0, 1.0, 2.0)


def test_hysteresis_from_conditions_is_the_threshold_state_machine():
    """Oracle: the threshold form hysteresis_lock (itself checked against a state machine) is the
    condition form with lose = C/N0 below the loss threshold and regain = C/N0 at or above the
    reacquisition threshold."""
    rng = np.random.default_rng(8)
    c = 19.5 + np.cumsum(rng.normal(0, 1.0, (300, 5)), axis=0) * 0.3
    for init in (True, False):
        np.testing.assert_array_equal(
            jg.hysteresis_from_conditions(c < 18.0, c >= 21.0, initially_locked=init),
            jg.hysteresis_lock(c, 18.0, 21.0, initially_locked=init),
        )
    with pytest.raises(ValueError, match="lose and regain"):
        jg.hysteresis_from_conditions(np.zeros((3, 2), bool), np.zeros((3, 3), bool))


def test_elevation_gain_linear_and_clipped():
    """Oracle: the stated pattern by hand: linear in elevation from the horizon gain (0 deg)
    to the zenith gain (90 deg), held outside [0, 90] deg, elementwise on arrays; with an
    exponent p the drop follows the zenith angle's p-th power."""
    e_deg = np.array([-30.0, 0.0, 30.0, 45.0, 90.0, 120.0])
    got = jg.elevation_gain_dbi(np.radians(e_deg), 3.0, -5.0)
    expected = -5.0 + 8.0 * np.clip(e_deg, 0.0, 90.0) / 90.0
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12)
    assert jg.elevation_gain_dbi(np.radians(60.0), 3.0, -5.0) == pytest.approx(-5.0 + 8.0 * 2 / 3, abs=1e-12)
    assert isinstance(jg.elevation_gain_dbi(0.3, 3.0, -5.0), float)
    z = (90.0 - np.clip(e_deg, 0.0, 90.0)) / 90.0
    np.testing.assert_allclose(
        jg.elevation_gain_dbi(np.radians(e_deg), 3.0, -5.0, 2.5), 3.0 - 8.0 * z**2.5, atol=1e-12
    )


def test_geometry_helpers_contracts():
    """Oracles by hand: slant range for one position given as a (3,) vector and for a batch,
    with an emitter off every axis (Euclidean distance, math.dist); free-space loss and
    received power default to a 0-dBi receive antenna; scalars give floats."""
    import math

    e = np.array([1200.0, -800.0, 300.0])
    p = np.array([[100.0, 2500.0, -6000.0], [-4000.0, 0.0, -2000.0]])
    r = jg.slant_range_m(p[0], e)
    assert isinstance(r, float) and r == pytest.approx(math.dist(p[0], e), rel=1e-15)
    np.testing.assert_allclose(jg.slant_range_m(p, e), [math.dist(x, e) for x in p], rtol=1e-15)
    assert isinstance(jg.free_space_loss_db(1e4, LAM), float)
    # each argument's shape is checked on its own, the other one being right
    with pytest.raises(ValueError, match=r"^emitter_ned_m must have shape \(3,\), got \(2,\)$"):
        jg.slant_range_m(p, e[:2])
    for bad in (p[:, :2], 5.0):
        with pytest.raises(ValueError, match=r"^position_ned_m must have shape \(\.\.\., 3\)"):
            jg.slant_range_m(bad, e)
    assert jg.received_jammer_power_dbw(30.0, 1e4, LAM) == pytest.approx(
        30.0 + 10 * np.log10((LAM / (4 * np.pi * 1e4)) ** 2), abs=1e-12
    )
    assert jg.threshold_range_m(30.0, -100.0, LAM) == pytest.approx(
        LAM / (4 * np.pi) * 10 ** (130.0 / 20), rel=1e-12
    )


def test_threshold_power_near_and_at_the_unjammed_cn0():
    """Oracle: the law in watts solved by hand, J* = Q Rc (C/gamma - N0), at a threshold only
    0.5 dB below the unjammed C/N0 (valid), and a threshold equal to it (no jammer power can
    do it: rejected by name)."""
    c_dbw, gamma = -160.0, 43.5  # C/N0 = 44 dB-Hz
    jstar_w = 2.0 * RC * (10 ** (c_dbw / 10) / 10 ** (gamma / 10) - 10 ** (N0 / 10))
    assert jg.jammer_power_at_threshold_dbw(c_dbw, gamma, N0, RC) == pytest.approx(
        10 * np.log10(jstar_w), abs=1e-9
    )
    with pytest.raises(ValueError, match="threshold_dbhz"):
        jg.jammer_power_at_threshold_dbw(c_dbw, 44.0, N0, RC)


def test_lock_thresholds_accept_equal_and_reject_infinite():
    """Contract: reacquisition equal to loss is a valid (no-hysteresis) receiver; an infinite
    threshold is rejected, naming the field."""
    th = jg.LockThresholds(18.0, 19.0, 18.0, 19.0)
    assert th.code_reacquisition == th.code_loss
    with pytest.raises(ValueError, match="code_reacquisition"):
        jg.LockThresholds(18.0, 19.0, float("inf"), 22.0)
    with pytest.raises(ValueError, match="carrier_reacquisition"):
        jg.LockThresholds(18.0, 19.0, 21.0, float("inf"))


def test_outage_intervals_accept_zero_one_flags():
    """Oracle: the same stretches as for booleans when availability is given as 0/1 integers."""
    t = np.arange(6.0)
    assert jg.outage_intervals(t, [1, 0, 0, 1, 0, 0]) == [(1.0, 3.0), (4.0, 5.0)]
