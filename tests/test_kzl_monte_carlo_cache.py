"""The in-process memo of the KZL Monte Carlo (navcore.papers.kzl_scenario.monte_carlo).

Oracle: the uncached computation, run_monte_carlo on the scenario the inputs give. A memoised
run equals it; a changed input the configuration reads misses (a new run, equal to its own
uncached computation); an input the stand-alone INS never reads (the visibility schedule) shares
the run and equals the uncached run at the changed input.
"""

from __future__ import annotations

import numpy as np
import pytest

from navcore.estimation.ekf_ins_gnss import monte_carlo_key, run_monte_carlo
from navcore.ledger.inputs import overriding, recording
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
