"""SP Sec. 2.6 mission set-up against the paper's printed event times and simple oracles."""

from __future__ import annotations

import numpy as np
import pytest

from navcore._validate import ModelDomainError
from navcore.claims.inputs import overriding
from navcore.integration.engine import CovarianceAnalysis, concatenate_analyses
from navcore.papers import sp_mission_flights as sc
from navcore.papers import sp_scenario_wiring as sw
from navcore.units import DEG, FT


def test_sequential_outage_events_match_printed_times():
    """Oracle: SP Sec. 2.6.1 prints first carrier loss 360 s, first code loss 1020 s, code
    reacquisition from 2760 s (= last code loss 1560 s + 20 min)."""
    ev = sc.sequential_outage_events(4)
    carrier_loss = sorted(t for t, _, k, on in ev if k == "carrier" and not on)
    code_loss = sorted(t for t, _, k, on in ev if k == "code" and not on)
    code_back = sorted(t for t, _, k, on in ev if k == "code" and on)
    assert carrier_loss == [360.0, 540.0, 720.0, 900.0]
    assert code_loss == [1020.0, 1200.0, 1380.0, 1560.0]
    assert code_back[0] == 2760.0
    # inverse order: the last channel lost is the first back
    first_back = min((e for e in ev if e[3]), key=lambda e: e[0])
    assert first_back[1] == 3 and first_back[2] == "code"
    assert not any(on for *_, on in sc.sequential_outage_events(4, outage_s=None))


def test_head_on_profile():
    """Oracle: SP Sec. 2.6.3 profile: about 40,000 ft, down to low level (200 ft class),
    pop-up to a few thousand feet at release."""
    tr = sc.head_on_trajectory()
    assert tr.h.max() / FT == pytest.approx(40_000, rel=0.03)
    assert tr.h[int(0.8 * len(tr))] / FT < 500
    assert 2000 < tr.h[-1] / FT < 6000


def _flight_path_angle(tr) -> np.ndarray:
    return np.arctan2(-tr.vel_ned[:, 2], np.hypot(tr.vel_ned[:, 0], tr.vel_ned[:, 1]))


@pytest.mark.parametrize(
    "override",
    [
        {},
        {"SP.missions.headon_climb_angle_deg": 20.0, "SP.missions.headon_dive_angle_deg": 30.0},
        {"SP.missions.headon_speed_mps": 230.0, "SP.missions.headon_pitch_rate_deg_s": 0.25},
    ],
)
def test_head_on_profile_meets_the_printed_altitudes(override):
    """Oracle: SP Sec. 2.6.3's printed 40,000 ft and 200 ft, within the height one 1-s step of the
    straight climb or dive covers (the profile is flown in whole steps), for any assumed speed and
    angle; the pop-up starts when the loosely coupled receiver loses lock, 159 s (Fig. 2.8) before
    release, read off the flight-path angle of the flown trajectory."""
    with overriding(override):
        tr = sc.head_on_trajectory()
        climb_step_m = sc.IN.headon_speed_mps * np.sin(sc.IN.headon_climb_angle_deg * DEG)
        dive_step_m = sc.IN.headon_speed_mps * np.sin(sc.IN.headon_dive_angle_deg * DEG)
    assert abs(tr.h.max() - 40_000 * FT) <= 0.5 * climb_step_m + 1.0
    # the ingress: level flight after the dive, before the pop-up
    gamma = _flight_path_angle(tr)
    popup = int(np.flatnonzero(gamma[:-1] > 1e-6)[-1])  # last climbing sample belongs to the pop-up
    start = popup - int(np.flatnonzero(gamma[popup::-1] <= 1e-9)[0]) + 1  # first sample of it
    ingress = tr.h[start - 100 : start]
    assert np.ptp(ingress) < 1e-6
    assert abs(ingress[0] - 200 * FT) <= 0.5 * dive_step_m + climb_step_m + 1.0
    assert tr.t[-1] - tr.t[start - 1] == pytest.approx(159.0)


def test_head_on_profile_out_of_its_domain():
    """A climb so steep and slow to accelerate that the acceleration alone passes 40,000 ft is a
    case the profile does not cover: ModelDomainError, not a trajectory that misses the altitude."""
    with (
        overriding(
            {
                "SP.missions.headon_climb_angle_deg": 40.0,
                "SP.missions.headon_acceleration_mps2": 0.5,
                "SP.missions.headon_takeoff_speed_mps": 100.0,
            }
        ),
        pytest.raises(ModelDomainError, match="head-on profile"),
    ):
        sc.head_on_segments()


def test_sequential_outage_turns():
    """Oracle: the heading of the flown trajectory: straight on the assumed initial heading for
    first_turn_s, then turns of turn_angle_deg, alternately right and left, every
    turn_interval_min."""
    with overriding({"SP.missions.heading_deg": 90.0, "SP.missions.turn_angle_deg": 45.0}):
        tr = sc.sequential_outage_trajectory(1800.0)
    heading = np.degrees(np.arctan2(tr.vel_ned[:, 1], tr.vel_ned[:, 0]))
    assert heading[[0, 240]] == pytest.approx([90.0, 90.0])
    assert heading[[600, 840, 1200, 1440]] == pytest.approx([135.0, 135.0, 90.0, 90.0])
    with (
        overriding({"SP.missions.turn_interval_min": 1.0}),
        pytest.raises(ModelDomainError, match="turn_interval_min"),
    ):
        sc.sequential_outage_trajectory(1800.0)


@pytest.mark.parametrize("period_s", [60.0, 120.0])
def test_helicopter_pull_ups_start_each_undulation(period_s):
    """Oracle: the flown trajectory's flight-path angle: each flagged pull-up starts where the
    angle is zero and rising (and the turns, every helicopter_turn_interval_min, shift the
    undulations off a fixed clock), so no pull-up is flagged on the way down."""
    with overriding({"SP.missions.helicopter_undulation_period_s": period_s}):
        tr = sc.helicopter_trajectory(1500.0)
        mask = sc.helicopter_pull_ups(tr.t, 2.0)
    gamma = _flight_path_angle(tr)
    starts = np.flatnonzero(mask & ~np.roll(mask, 1))
    assert len(starts) >= 1500.0 / (period_s + 30.0) - 1
    # each loss starts where the angle is zero and rising (the flight's start, t = 0, excluded:
    # its loss starts one step later)
    assert not mask[0] and starts[0] == 1
    assert np.all(np.abs(gamma[starts[1:]]) < 1e-9)
    assert np.all(np.diff(gamma)[starts] > 0.0)


def _fake(P: np.ndarray) -> CovarianceAnalysis:
    lay = sw.truth_layout()
    t = np.array([0.0, 1.0])
    z = np.zeros((2, lay.size))
    return CovarianceAnalysis(t, lay, lay, z, z, np.zeros(2), np.zeros(2), np.zeros(2, int), {1: P}, P, P)


def test_target_location_sigma_closed_form():
    """Oracle: target error = position error when attitude is exact; = range x heading
    error when position is exact (level target 8 km away, heading error only)."""
    lay = sw.truth_layout()
    P = np.zeros((lay.size, lay.size))
    P[0, 0] = P[1, 1] = 50.0**2
    assert sc.target_location_sigma(_fake(P), 8000.0) == pytest.approx(50.0 * np.sqrt(2))
    P[:] = 0.0
    a = lay.index("misalignment", 2)
    P[a, a] = 1e-3**2
    assert sc.target_location_sigma(_fake(P), 8000.0) == pytest.approx(8.0, rel=1e-9)


def test_concatenate_analyses_drops_shared_sample():
    """Oracle: two parts of 3 and 2 samples sharing t = 2 give 4 samples."""
    lay = sw.truth_layout()

    def part(t):
        n = len(t)
        z = np.zeros((n, lay.size))
        return CovarianceAnalysis(np.array(t), lay, lay, z, z, np.array(t), np.array(t), np.zeros(n, int), {})

    c = concatenate_analyses([part([0.0, 1.0, 2.0]), part([2.0, 3.0])])
    assert c.t.tolist() == [0.0, 1.0, 2.0, 3.0]
    with pytest.raises(ValueError, match="consecutive"):
        concatenate_analyses([part([0.0, 1.0]), part([5.0, 6.0])])


def test_grade_label_erratum_monte_carlo():
    """SP-E-grade-labels evidence: a seeded Monte Carlo of the same error model agrees with the
    covariance propagation (the claims are inconsistent, so the ledger runs no oracle)."""
    from navcore.papers import sp_missions as spm

    assert spm.grade_cep_monte_carlo_nmi(1.0, runs=5000) == pytest.approx(spm.grade_cep_nmi()[1.0], rel=0.04)


def test_stationary_runs_are_converged_in_their_step():
    """Oracle: a ten times finer step (1 s instead of at most 10 s) gives the same 1-h grade CEPs
    and the same noise-only error, to 1e-8 relative: the step is a resolution, not an input (the
    discretisation of the constant dynamics at rest is exact to the series' rounding), and every
    run ends at its nominal time whatever the step."""
    from navcore.papers import sp_missions as spm

    coarse, fine = spm.grade_cep_nmi(), spm.grade_cep_nmi(max_step_s=1.0)
    for g, v in coarse.items():
        assert fine[g] == pytest.approx(v, rel=1e-8)
    assert spm.noise_only_error_m(10.0, 19.0, max_step_s=1.0) == pytest.approx(
        spm.noise_only_error_m(10.0, 19.0), rel=1e-8
    )
    # a step that does not divide the run is shortened, never the run lengthened
    assert spm.noise_only_error_m(10.0, 19.0, max_step_s=7.0) == pytest.approx(
        spm.noise_only_error_m(10.0, 19.0), rel=1e-8
    )


def test_scale_initial_errors_scales_the_blocks_and_their_correlations():
    """Oracle: the covariance of a scaled random vector, D P D with D diagonal (2 on the
    position and velocity states, 0.5 on the psi angle), built by hand on a random positive
    definite matrix; the clock offset replaced by its new sigma with no correlation."""
    import numpy as np

    from navcore.papers import sp_mission_flights as sc
    from navcore.papers import sp_scenario_wiring as sw

    lay = sw.truth_layout(channels=4)
    rng = np.random.default_rng(4)
    A = rng.standard_normal((lay.size, lay.size))
    P = A @ A.T
    d = np.ones(lay.size)
    for block, f in (("position", 2.0), ("velocity", 2.0), ("misalignment", 0.5)):
        d[lay.slice(block)] = f
    got = sc.scale_initial_errors(2.0, 0.5, clock_offset_m=1499.0)(P, lay)
    want = np.diag(d) @ P @ np.diag(d)
    i = lay.index("clock bias")
    want[i, :] = want[:, i] = 0.0
    want[i, i] = 1499.0**2
    np.testing.assert_allclose(got, want, rtol=1e-14)
    np.testing.assert_array_equal(sc.scale_initial_errors()(P, lay), P)


def test_free_inertial_variant_is_one_unbroken_run_without_reacquisition():
    """The free-inertial variant (84 min without GPS after the last code loss) is run in
    phases that share the mission up to reacquisition with the other variant. Oracle: the
    same mission run in one piece, from take-off to its end, with the events of no
    reacquisition. The phases used to apply a phase's last-sample measurements twice (the
    barometer at the last code loss) and to give the free-inertial variant the first
    reacquired pseudorange at 2760 s (its error fell from 3908 to 3194 m for the 10 nmi/h
    system, though GPS never returns)."""
    phased = sc.sequential_outage(free_inertial=True, architecture="tight")
    tr = sc.sequential_outage_trajectory(sc.end_free_s())
    channels = sc._channels(sc.end_free_s())
    events = sc.sequential_outage_events(len(channels), outage_s=None)
    code, carrier = sc.lock_table(tr.t, len(channels), events)
    systems = sc._group("tight")
    whole = sw._run(systems, tr, code, carrier, channels)
    for s in systems:
        np.testing.assert_allclose(phased[s].t, whole[s].t)
        np.testing.assert_allclose(phased[s].horizontal_position, whole[s].horizontal_position, rtol=1e-6)
