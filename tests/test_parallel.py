"""The executor interface: serial, loky workers and a dask cluster give the same numbers.

Oracle: the serial run of the same tasks (the same code in the calling process); the dask
path runs on a ``dask.distributed.LocalCluster`` in this process (threads, no network).
"""

from __future__ import annotations

import numpy as np
import pytest

from navcore.inertial.imu import ImuSpec
from navcore.integration.ekf_ins_gnss import GnssNoise, Scenario, run_monte_carlo
from navcore.parallel import effective_jobs, run_tasks, task_seeds


def _scenario() -> Scenario:
    """Five seconds of level flight over four fixed satellites (the docstring's example)."""
    sats = np.array([[2e7, 0.0, -1e7], [-2e7, 0.0, -1e7], [0.0, 2e7, -1e7], [0.0, -2e7, -1e7]])
    return Scenario(
        velocity_ned=np.array([100.0, 0.0, 0.0]),
        attitude=np.zeros(3),
        duration=5.0,
        imu_rate=100.0,
        gps_rate=1.0,
        imu=ImuSpec("test", accel_bias=1e-2),
        sat_pos_ned=np.tile(sats, (6, 1, 1)),
        sat_vel_ned=np.zeros((6, 4, 3)),
        n_visible=np.full(6, 4),
        gnss=GnssNoise(3.0, 0.1, None, None),
        init_time=None,
        pos0_sigma=3.0,
        vel0_sigma=0.1,
        baselines_b=None,
    )


_FIELDS = ("pos_err", "vel_err", "att_err", "pos_sigma", "vel_sigma", "att_sigma")


def _same(a, b) -> bool:
    return all(np.array_equal(getattr(a, f), getattr(b, f)) for f in _FIELDS)


def _draw(seed: np.random.SeedSequence, n: int) -> np.ndarray:
    return np.random.default_rng(seed).standard_normal(n)


def test_run_tasks_keeps_the_order_of_the_tasks_on_workers():
    """Oracle: the list comprehension the serial path is."""
    tasks = [(seed, 3) for seed in task_seeds(11, 5)]
    serial = run_tasks(_draw, tasks)
    parallel = run_tasks(_draw, tasks, n_jobs=2)
    assert len(serial) == 5
    assert all(np.array_equal(a, b) for a, b in zip(serial, parallel, strict=True))
    assert [np.array_equal(serial[0], s) for s in serial[1:]] == [False] * 4  # independent streams


def test_task_seeds_and_jobs_refuse_bad_values():
    with pytest.raises(ValueError, match="n_tasks"):
        task_seeds(1, 0)
    with pytest.raises(ValueError, match="seed"):
        task_seeds(-1, 2)
    with pytest.raises(TypeError, match="n_jobs"):
        effective_jobs(1.5)  # type: ignore[arg-type]
    assert effective_jobs(None) == effective_jobs(1) == 1


def test_one_batch_is_the_single_stream_and_batches_are_independent_of_workers():
    """``batches=1`` is the historical single stream; a split run gives the same numbers
    serially and on two loky workers, and its runs are those of each batch run alone."""
    sc = _scenario()
    whole = run_monte_carlo(sc, "tc", 12, seed=3, initialise=False)
    split = run_monte_carlo(sc, "tc", 12, seed=3, initialise=False, batches=3)
    split_par = run_monte_carlo(sc, "tc", 12, seed=3, initialise=False, batches=3, n_jobs=2)
    assert _same(split, split_par)
    assert not np.array_equal(whole.pos_err, split.pos_err)  # other seeds, other draws
    first = run_monte_carlo(sc, "tc", 4, seed=0, initialise=False)  # not the child stream
    assert not np.array_equal(first.pos_err, split.pos_err[:4])
    # the run-averaged 1-sigma is the root of the runs' mean variance: batches weigh by runs
    assert split.pos_sigma.shape == whole.pos_sigma.shape
    with pytest.raises(ValueError, match="batches must be at most n_runs"):
        run_monte_carlo(sc, "tc", 2, seed=3, initialise=False, batches=3)


def test_dask_backend_gives_the_serial_numbers():
    """joblib's dask backend on a LocalCluster runs the same Monte Carlo batches and the same
    ledger tasks to the same numbers (oracle: the serial runs in this process)."""
    distributed = pytest.importorskip(
        "distributed", reason="dask is an optional extra (pip install navcore[dask])"
    )
    import joblib

    from navcore.ledger import evaluate, registry
    from navcore.ledger.tables import json_dump

    sc = _scenario()
    serial = run_monte_carlo(sc, "tc", 8, seed=5, initialise=False, batches=2)
    with (
        # in this process, one thread: CPython 3.11 can fail ("AST constructor recursion depth
        # mismatch") when two threads import modules that parse annotations at the same time
        distributed.LocalCluster(
            n_workers=1, threads_per_worker=1, processes=False, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster),
        joblib.parallel_config(backend="dask"),
    ):
        on_dask = run_monte_carlo(sc, "tc", 8, seed=5, initialise=False, batches=2, n_jobs=-1)
        drawn = run_tasks(_draw, [(s, 4) for s in task_seeds(2, 3)], n_jobs=-1)
        ids = [c.id for c in registry.claims("WF")][:6] + [c.id for c in registry.claims("ATC10")][:6]
        registry.evaluate_claim.cache_clear()
        try:
            registry.evaluate_in_parallel(ids, n_jobs=-1)  # the ledger's tasks on the cluster
            ledger_on_dask = json_dump([registry.evaluate_claim(i) for i in ids])
        finally:
            registry.evaluate_claim.cache_clear()
    assert ledger_on_dask == json_dump([evaluate(registry.claim(i)) for i in ids])
    assert _same(serial, on_dask)
    assert all(
        np.array_equal(a, b)
        for a, b in zip(drawn, run_tasks(_draw, [(s, 4) for s in task_seeds(2, 3)]), strict=True)
    )


def test_parallel_ledger_is_the_serial_ledger(monkeypatch):
    """Claims evaluated on two workers give the serial evaluations, field for field.

    Oracle: :func:`navcore.ledger.evaluate` of each claim in this process.
    """
    from navcore.ledger import evaluate, registry
    from navcore.ledger.tables import json_dump

    monkeypatch.setenv("NAVCORE_CACHE", "off")  # every claim goes to a worker

    ids = [c.id for c in registry.claims("WF")][:12] + [c.id for c in registry.claims("KZL")][:6]
    registry.evaluate_claim.cache_clear()
    try:
        seconds = registry.evaluate_in_parallel(ids, n_jobs=2)
        assert set(seconds) == set(ids)
        parallel = [registry.evaluate_claim(i) for i in ids]
    finally:
        registry.evaluate_claim.cache_clear()
    serial = [evaluate(registry.claim(i)) for i in ids]
    assert json_dump(parallel) == json_dump(serial)


def test_claim_dependencies_follow_the_imports():
    """A KZL Monte Carlo claim depends on the EKF and the strapdown, not on the detection models."""
    from navcore.ledger import registry

    deps = registry.claim_dependencies("KZL-fig4-dd-phases-robust")
    assert {"integration/ekf_ins_gnss.py", "inertial/strapdown.py", "papers/kzl_scenario.py"} <= set(deps)
    assert not any(d.startswith("detection/") for d in deps)
    assert "claims/runs.py" in deps and "papers/paper_items.json" in deps
