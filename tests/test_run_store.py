"""The disk store of model runs (navcore.claims.run_store) on a synthetic run.

Oracle: the run computed directly. A stored run reads back equal (and read-only) in a fresh
store object, without the run being called again; a changed argument (the run's key), a changed
source module or the bypass variable misses; a damaged argument fails at the boundary, naming it.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from navcore.claims import run_store as rs
from navcore.claims.run_store import RunStore, read_only


@dataclasses.dataclass
class Run:
    pos_err: np.ndarray
    sigma: np.ndarray


def _run(seed: int) -> Run:
    rng = np.random.default_rng(seed)
    return Run(pos_err=rng.normal(size=(5, 3)), sigma=np.abs(rng.normal(size=5)))


@pytest.fixture(autouse=True)
def _store_on(monkeypatch):
    monkeypatch.delenv(rs.DISABLE_VARIABLE, raising=False)


def _store(tmp_path, modules=("navcore.units",)) -> RunStore:
    return RunStore("runs", modules=modules, root=tmp_path)


def test_stored_run_reads_back_without_running(tmp_path):
    calls = []

    def run():
        calls.append(1)
        return _run(7)

    first = _store(tmp_path).read_or_run("seed=7", "tc-True", Run, run)
    again = _store(tmp_path).read_or_run("seed=7", "tc-True", Run, run)  # a fresh store object
    oracle = _run(7)
    assert calls == [1]
    for got in (first, again):
        assert np.array_equal(got.pos_err, oracle.pos_err) and np.array_equal(got.sigma, oracle.sigma)
        assert not got.pos_err.flags.writeable and not got.sigma.flags.writeable
    (path,) = (tmp_path / "runs").glob("*.npz")  # one file, no temporary left behind
    assert path.name.startswith("tc-True-") and path == _store(tmp_path).path("seed=7", "tc-True")


def test_key_changes_with_the_argument_and_the_sources(tmp_path):
    store = _store(tmp_path)
    key = store.key("seed=7")
    assert key == _store(tmp_path).key("seed=7") and len(key) == 24
    assert store.key("seed=8") != key  # another argument
    assert _store(tmp_path, ("navcore.formatting",)).key("seed=7") != key  # another model source
    store.write("seed=7", "tc", _run(7))
    assert store.read("seed=8", "tc", Run) is None  # another argument misses
    assert store.read("seed=7", "tc", Run) is not None
    # the label names the file only; the key alone decides
    assert store.path("seed=7", "a").name[2:] == store.path("seed=7", "b").name[2:]


def test_bypass_reads_and_writes_nothing(tmp_path, monkeypatch):
    store = _store(tmp_path)
    store.write("seed=7", "tc", _run(7))
    monkeypatch.setenv(rs.DISABLE_VARIABLE, "1")
    assert store.path("seed=7", "tc") is None and store.read("seed=7", "tc", Run) is None
    got = store.read_or_run("seed=7", "tc", Run, lambda: _run(9))  # computed, not read
    assert np.array_equal(got.pos_err, _run(9).pos_err) and not got.pos_err.flags.writeable
    store.write("seed=9", "tc", _run(9))
    assert len(list((tmp_path / "runs").glob("*.npz"))) == 1


def test_default_root_is_the_temporary_directory(monkeypatch, tmp_path):
    monkeypatch.setattr(rs.tempfile, "gettempdir", lambda: str(tmp_path))
    path = RunStore("runs", modules=("navcore.units",)).path("k", "x")
    assert path is not None and path.parent == tmp_path / "runs"


@pytest.mark.parametrize(
    ("kwargs", "argument"),
    [
        ({"name": "", "modules": ("navcore.units",)}, "name"),
        ({"name": "a/b", "modules": ("navcore.units",)}, "name"),
        ({"name": "..", "modules": ("navcore.units",)}, "name"),
        ({"name": "runs", "modules": ()}, "modules"),
        ({"name": "runs", "modules": "navcore.units"}, "modules"),
    ],
)
def test_bad_store_arguments(kwargs, argument):
    with pytest.raises(ValueError, match=argument):
        RunStore(**kwargs)


def test_bad_run_arguments(tmp_path):
    store = _store(tmp_path)
    with pytest.raises(ValueError, match="label"):
        store.path("k", "a/b")
    with pytest.raises(ValueError, match="run_key"):
        store.key(7)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="kind"):
        store.read("k", "x", dict)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="result"):
        store.write("k", "x", {"pos_err": np.ones(2)})
    with pytest.raises(ValueError, match="result field 'sigma'"):
        read_only(Run(pos_err=np.ones(2), sigma=[1.0]))  # type: ignore[arg-type]
