"""The in-process memo of the KZL Monte Carlo (navcore.papers.kzl_scenario.monte_carlo).

Oracle: the uncached computation, run_monte_carlo on the scenario the inputs give. A memoised
run equals it; a changed input the configuration reads misses (a new run, equal to its own
uncached computation); an input the stand-alone INS never reads (the visibility schedule) shares
the run and equals the uncached run at the changed input.
"""

from __future__ import annotations

import numpy as np
import pytest

from navcore.claims.inputs import band_ahead, overriding, recording
from navcore.integration.ekf_ins_gnss import monte_carlo_key, run_monte_carlo, run_monte_carlo_batch
from navcore.papers import kzl_scenario as S

FIELDS = ("pos_err", "vel_err", "att_err", "pos_sigma", "vel_sigma", "att_sigma")


@pytest.fixture(autouse=True)
def _fresh(monkeypatch):
    monkeypatch.setenv("NAVCORE_NO_DISK_CACHE", "1")
    S.monte_carlo.cache_clear()
    S._RUNS.clear()
    calls = []
    real = S.run_monte_carlo

    def counted(*args, **kwargs):
        calls.append(args[1])
        return real(*args, **kwargs)

    monkeypatch.setattr(S, "run_monte_carlo", counted)
    yield calls
    S.monte_carlo.cache_clear()
    S._RUNS.clear()


def _uncached(mode: str, initialise: bool = True):
    sc = S.table1_scenario(mode, initialise)
    return sc, run_monte_carlo(sc, mode, S.n_runs(), S.SEED, initialise=initialise)


def _same(a, b) -> bool:
    return all(np.array_equal(getattr(a, f), getattr(b, f)) for f in FIELDS)


def test_memoised_run_equals_uncached_and_changed_input_misses(_fresh):
    calls = _fresh
    with recording():
        first = S.monte_carlo("tc")
        S.monte_carlo.cache_clear()  # the input cache forgets; the run memo answers
        again = S.monte_carlo("tc")
        _, oracle = _uncached("tc")
    assert calls == ["tc"] and _same(first, oracle) and _same(again, oracle)
    assert not again.pos_err.flags.writeable  # shared: read-only
    with overriding({"KZL.scenario.code_noise_m": 6.0}), recording():
        moved = S.monte_carlo("tc")
        _, oracle_moved = _uncached("tc")
    assert calls == ["tc", "tc"]  # a changed input the configuration reads is a new run
    assert _same(moved, oracle_moved) and not _same(moved, first)


def test_ins_shares_runs_across_schedules(_fresh):
    calls = _fresh
    with recording():
        nominal = S.monte_carlo("ins")
    with overriding({"KZL.scenario.short_segment_s": 20.0}), recording():
        other = S.monte_carlo("ins")
        sc, oracle = _uncached("ins")
    assert calls == ["ins"]  # the stand-alone INS reads no schedule: one run
    assert _same(other, oracle) and _same(other, nominal)
    assert np.array_equal(other.n_visible, sc.n_visible)  # the result still echoes its schedule
    assert not np.array_equal(other.n_visible, nominal.n_visible)
    with overriding({"KZL.scenario.short_segment_s": 20.0}), recording():
        tc = S.table1_scenario("tc")
    with recording():
        tc_nominal = S.table1_scenario("tc")
    assert monte_carlo_key(tc, "tc", 30, S.SEED) != monte_carlo_key(
        tc_nominal, "tc", 30, S.SEED
    )  # an aided filter reads the schedule


def test_key_holds_every_argument():
    with recording():
        sc = S.table1_scenario("tc_att")
    base = monte_carlo_key(sc, "tc_att", 30, 1)
    assert monte_carlo_key(sc, "tc_att", 30, 1) == base
    assert monte_carlo_key(sc, "tc_att", 60, 1) != base
    assert monte_carlo_key(sc, "tc_att", 30, 2) != base
    assert monte_carlo_key(sc, "tc_att", 30, 1, initialise=False) != base
    assert monte_carlo_key(sc, "tc_att", 30, 1, attitude_min_sats=5) != base
    assert monte_carlo_key(sc, "tc_att", 30, 1, batches=2) != base
    assert monte_carlo_key(sc, "tc_dd", 30, 1) != base
    with pytest.raises(ValueError, match="mode"):
        monte_carlo_key(sc, "loose", 30, 1)


# --- a band's runs in one batched call ------------------------------------------------------------

BAND = (
    {"KZL.scenario.code_noise_m": 6.0},
    {"KZL.scenario.short_segment_s": 20.0},  # another schedule: other satellite counts per epoch
    {"KZL.scenario.phase_noise_m": 0.0015, "KZL.scenario.init_time_s": 150.0},
    {"KZL.scenario.attitude_noise_rad": 0.006, "KZL.scenario.crab_angle_deg": 1.0},
)
# a small ensemble and a shorter flight keep the tests short (the schedule's four short segments
# still end the flight: 8, 4, 3, 2, 5 satellites from 0, 20, 40, 60, 80 s at 20-s segments)
FEW = {"KZL.scenario.n_runs": 6, "KZL.scenario.duration_s": 100.0}


def _close(a, b) -> bool:
    return all(np.allclose(getattr(a, f), getattr(b, f), rtol=1e-10, atol=0.0) for f in FIELDS)


@pytest.mark.parametrize("mode", ["tc_att", "tc_dd"])
def test_batched_scenarios_equal_one_call_each(mode):
    # oracle: the unbatched Monte Carlo, one run_monte_carlo call per scenario
    scs = []
    for ov in ({}, *BAND):
        with overriding({**FEW, **ov}), recording():
            scs.append(S.table1_scenario(mode))
    batched = run_monte_carlo_batch(scs, mode, 6, S.SEED)
    for sc, got in zip(scs, batched, strict=True):
        assert _close(got, run_monte_carlo(sc, mode, 6, S.SEED))
        assert np.array_equal(got.n_visible, sc.n_visible)
    assert not _close(batched[0], batched[1])  # the scenarios do differ


def test_batch_rejects_scenarios_that_cannot_share_arrays():
    with recording():
        sc = S.table1_scenario("tc")
    with overriding({"KZL.scenario.constellation": (6, 4, 55.0, 0.0)}), recording():  # another sky
        other_sky = S.table1_scenario("tc")
    with pytest.raises(ValueError, match="scenarios must share"):
        run_monte_carlo_batch([sc, other_sky], "tc", 2, S.SEED)
    with pytest.raises(ValueError, match="at least one"):
        run_monte_carlo_batch([], "tc", 2, S.SEED)


def test_announced_band_is_one_batched_call_and_gives_the_unbatched_runs(_fresh, monkeypatch):
    # oracle: run_monte_carlo on the scenario each run's inputs give (one call per run)
    calls = _fresh
    batches = []
    real = S.run_monte_carlo_batch

    def counted(scenarios, *args, **kwargs):
        batches.append(len(scenarios))
        return real(scenarios, *args, **kwargs)

    monkeypatch.setattr(S, "run_monte_carlo_batch", counted)
    runs = [{**FEW, **ov} for ov in BAND]
    with overriding(FEW), band_ahead(runs):
        got = []
        for ov in runs:
            with overriding(ov), recording() as reads:
                got.append(S.monte_carlo("tc_dd"))
            assert "KZL.scenario.code_noise_m" in reads  # the caller still records what a run reads
    assert batches == [len(runs)] and calls == []  # one batched call, no run of its own
    for ov, result in zip(runs, got, strict=True):
        with overriding(ov), recording():
            sc = S.table1_scenario("tc_dd")
        assert _close(result, run_monte_carlo(sc, "tc_dd", 6, S.SEED))
        assert not result.pos_err.flags.writeable
