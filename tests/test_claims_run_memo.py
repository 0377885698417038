"""The in-process memo of model runs before a disk store (navcore.claims.run_store.RunMemo).

Oracles: a synthetic run whose numbers follow from its seed alone (``_run``), computed directly;
counting fakes of the run and batch functions, which record every key computed and every call's
items; and LRU orders and call splits written out by hand. Each key is computed once across
memory, disk and batches; a batch gives the runs of one-by-one calls; a group is split at the
row bound; a damaged argument fails at the boundary, naming it.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from navcore.claims import run_store as rs
from navcore.claims.run_store import RunMemo, RunStore


@dataclasses.dataclass
class Run:
    err: np.ndarray


def _run(seed: int) -> Run:
    return Run(err=np.random.default_rng(seed).normal(size=4))


def _key(seed: int) -> str:
    return f"seed={seed}"


@pytest.fixture(autouse=True)
def _store_on(monkeypatch):
    monkeypatch.delenv(rs.DISABLE_VARIABLE, raising=False)


def _memo(tmp_path, size: int = 8) -> RunMemo[Run]:
    return RunMemo(RunStore("runs", modules=("navcore.units",), root=tmp_path), Run, size=size)


class Counter:
    """Fake run functions that record what they compute."""

    def __init__(self) -> None:
        self.computed: list[int] = []  # every seed computed, one-by-one or batched
        self.calls: list[list[int]] = []  # the seeds of each batched call

    def one(self, seed: int):
        def run() -> Run:
            self.computed.append(seed)
            return _run(seed)

        return run

    def batch(self, seeds: list[int]) -> list[Run]:
        self.calls.append(list(seeds))
        self.computed.extend(seeds)
        return [_run(s) for s in seeds]


def _batched(memo, seeds, counter, *, rows_per_call=100, group=lambda s: 0, rows=lambda s: 1):
    return memo.get_or_run_batched(
        seeds,
        key=_key,
        label=lambda s: "demo",
        group=group,
        rows=rows,
        run_batch=counter.batch,
        rows_per_call=rows_per_call,
    )


def _same(got: Run, seed: int) -> bool:
    return np.array_equal(got.err, _run(seed).err)


def test_each_key_is_computed_once_across_memory_disk_and_batches(tmp_path):
    counter = Counter()
    memo = _memo(tmp_path)
    assert _same(memo.get_or_run(_key(1), "demo", counter.one(1)), 1)
    assert _same(memo.get_or_run(_key(1), "demo", counter.one(1)), 1)  # memory
    got = _batched(memo, [1, 2, 3, 2], counter)  # 1 in memory, 2 repeated
    assert [_same(r, s) for r, s in zip(got, [1, 2, 3, 2], strict=True)] == [True] * 4
    assert got[1] is got[3]  # one run for the repeated key
    fresh = _memo(tmp_path)  # another process: nothing in memory, everything on disk
    again = _batched(fresh, [3, 2, 1], counter)
    assert _same(fresh.get_or_run(_key(2), "demo", counter.one(2)), 2)
    assert [_same(r, s) for r, s in zip(again, [3, 2, 1], strict=True)] == [True] * 3
    assert counter.computed == [1, 2, 3] and counter.calls == [[2, 3]]
    assert fresh.keys() == (_key(3), _key(1), _key(2))  # read from disk, then kept
    assert all(not r.err.flags.writeable for r in again)


def test_least_recently_used_is_forgotten_first(tmp_path, monkeypatch):
    monkeypatch.setenv(rs.DISABLE_VARIABLE, "1")  # no disk: a forgotten run is computed again
    counter = Counter()
    memo = _memo(tmp_path, size=3)
    for seed in (1, 2, 3):
        memo.get_or_run(_key(seed), "demo", counter.one(seed))
    assert memo.keys() == ("seed=1", "seed=2", "seed=3")
    memo.get_or_run(_key(1), "demo", counter.one(1))  # a lookup that finds 1 uses it
    assert memo.keys() == ("seed=2", "seed=3", "seed=1")
    memo.get_or_run(_key(4), "demo", counter.one(4))  # one more: 2 is forgotten
    assert memo.keys() == ("seed=3", "seed=1", "seed=4") and len(memo) == 3
    assert _key(2) not in memo and _key(4) in memo
    # 5 is missing (queued), 1 is found (used: after 4); then 5 is made and kept: 3 is forgotten
    _batched(memo, [5, 1], counter)
    assert memo.keys() == ("seed=4", "seed=1", "seed=5")
    memo.get_or_run(_key(2), "demo", counter.one(2))
    assert counter.computed == [1, 2, 3, 4, 5, 2]  # 2 was forgotten, so computed again
    assert memo.keys() == ("seed=1", "seed=5", "seed=2")
    memo.clear()
    assert len(memo) == 0 and memo.keys() == ()


def test_batch_gives_the_runs_of_one_by_one_calls(tmp_path):
    seeds = [7, 3, 11, 5, 3, 8]
    counter = Counter()
    got = _batched(_memo(tmp_path / "a"), seeds, counter, rows_per_call=2, group=lambda s: s % 2)
    one = _memo(tmp_path / "b")
    oracle = [one.get_or_run(_key(s), "demo", lambda s=s: _run(s)) for s in seeds]
    assert [r.err.tolist() for r in got] == [r.err.tolist() for r in oracle]
    assert [r.err.tolist() for r in got] == [_run(s).err.tolist() for s in seeds]
    # odd seeds first (7 comes first), each group in order, two per call
    assert counter.calls == [[7, 3], [11, 5], [8]]


def test_groups_split_at_the_row_bound(tmp_path, monkeypatch):
    monkeypatch.setenv(rs.DISABLE_VARIABLE, "1")
    rows = {1: 30, 2: 30, 3: 30, 4: 30, 5: 30, 6: 30, 7: 30, 8: 30, 9: 30}.__getitem__
    counter = Counter()
    _batched(_memo(tmp_path, size=20), list(range(1, 10)), counter, rows_per_call=240, rows=rows)
    assert counter.calls == [[1, 2, 3, 4, 5, 6, 7, 8], [9]]  # 8 runs of 30 rows fill 240
    counter = Counter()
    _batched(_memo(tmp_path, size=20), [1, 2, 3], counter, rows_per_call=20, rows=rows)
    assert counter.calls == [[1], [2], [3]]  # a run of more rows than the bound is a call alone
    sizes = {1: 2, 2: 3, 3: 1, 4: 4, 5: 1}.__getitem__
    counter = Counter()
    _batched(_memo(tmp_path, size=20), [1, 2, 3, 4, 5], counter, rows_per_call=5, rows=sizes)
    assert counter.calls == [[1, 2], [3, 4], [5]]  # 2+3 = 5; 1+4 = 5; 1


def test_runs_are_stored_under_their_label(tmp_path):
    memo = _memo(tmp_path)
    memo.get_or_run_batched(
        [1, 2],
        key=_key,
        label=lambda s: f"tc-{s}",
        group=lambda s: 0,
        rows=lambda s: 1,
        run_batch=Counter().batch,
        rows_per_call=1,
    )
    names = sorted(p.name for p in (tmp_path / "runs").glob("*.npz"))
    assert names == sorted(memo.store.path(_key(s), f"tc-{s}").name for s in (1, 2))


def test_bypassed_store_writes_nothing_and_memory_still_keeps(tmp_path, monkeypatch):
    monkeypatch.setenv(rs.DISABLE_VARIABLE, "1")
    counter = Counter()
    memo = _memo(tmp_path)
    _batched(memo, [1, 2], counter)
    memo.get_or_run(_key(1), "demo", counter.one(1))
    assert counter.computed == [1, 2] and not (tmp_path / "runs").exists()


@pytest.mark.parametrize(
    ("kwargs", "error", "argument"),
    [
        ({"store": "runs"}, TypeError, "store"),
        ({"kind": dict}, ValueError, "kind"),
        ({"size": 0}, ValueError, "size"),
        ({"size": -3}, ValueError, "size"),
        ({"size": 2.0}, TypeError, "size"),
        ({"size": True}, TypeError, "size"),
    ],
)
def test_bad_memo_arguments(tmp_path, kwargs, error, argument):
    args = {"store": RunStore("runs", modules=("navcore.units",), root=tmp_path), "kind": Run, "size": 4}
    with pytest.raises(error, match=argument):
        RunMemo(**{**args, **kwargs})


def test_bad_run_arguments(tmp_path):
    memo = _memo(tmp_path)
    with pytest.raises(TypeError, match="key"):
        memo.get_or_run(7, "demo", lambda: _run(7))  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="label"):
        memo.get_or_run("k", "a/b", lambda: _run(7))
    with pytest.raises(TypeError, match="run"):
        memo.get_or_run("k", "demo", _run(7))  # type: ignore[arg-type]
    counter = Counter()
    for kwargs, error, argument in [
        ({"rows_per_call": 0}, ValueError, "rows_per_call"),
        ({"rows_per_call": 2.5}, TypeError, "rows_per_call"),
        ({"rows": lambda s: 0}, ValueError, "rows"),
        ({"rows": lambda s: 1.0}, TypeError, "rows"),
        ({"key": lambda s: s}, TypeError, "key"),
        ({"label": lambda s: ""}, ValueError, "label"),
        ({"run_batch": lambda seeds: [_run(1)]}, ValueError, "run_batch"),
    ]:
        args = {
            "key": _key,
            "label": lambda s: "demo",
            "group": lambda s: 0,
            "rows": lambda s: 1,
            "run_batch": counter.batch,
            "rows_per_call": 4,
        }
        with pytest.raises(error, match=argument):
            memo.get_or_run_batched([1, 2], **{**args, **kwargs})
    assert len(memo) == 0 and counter.computed == []  # nothing was kept from a failed call
