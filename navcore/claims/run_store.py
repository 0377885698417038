"""Model runs kept between calls: on disk between processes, and in memory within one.

A paper's Monte Carlo can take seconds to minutes, and the chapter's notebooks, the ledger and
the tests ask for the same runs. A :class:`RunStore` keeps each run as an ``.npz`` file in a
directory of its own (under the system temporary directory by default), named by a key hashed
from the sources of the modules that compute the run, from this module's source, from the
run's key (a text that holds every argument of the run) and from numpy's version: a changed
model, a changed argument or another numpy misses and is computed afresh.

Set the environment variable ``NAVCORE_NO_DISK_CACHE`` (to any text that is not empty) to
bypass every store: nothing is read or written, and each run is computed. The ledger's own
cache of evaluated claims (``NAVCORE_CACHE``) is another one: it does not switch this store.

A run is a dataclass whose fields are all numpy arrays; what the store returns has its arrays
made read-only (:func:`read_only`), since one result is shared by every caller of its key.

A :class:`RunMemo` stands in front of a store: the runs this process made or read, the most
recently used kept, so that the claims and band corners that ask for one run share it without
reading its file again. It also makes many runs at once (:meth:`RunMemo.get_or_run_batched`):
the runs of a ledger band that a model announces
(:func:`~navcore.claims.inputs.for_each_band_run`) and that neither memory nor disk holds, in
batched calls of a bounded size. The memo lives in this module because it writes the store's
files: which result is kept under which key is part of every key's hash (this module's source),
like the file format.

Example
-------
>>> import dataclasses, tempfile
>>> import numpy as np
>>> @dataclasses.dataclass
... class Run:
...     err: np.ndarray
>>> store = RunStore("doc-runs", modules=("navcore.units",), root=Path(tempfile.mkdtemp()))
>>> run = store.read_or_run("seed=1", "demo", Run, lambda: Run(err=np.arange(3.0)))
>>> run.err.tolist(), run.err.flags.writeable
([0.0, 1.0, 2.0], False)

A second call with the key ``"seed=1"`` reads the file and does not call its ``run``.
"""

from __future__ import annotations

import dataclasses
import hashlib
import importlib
import inspect
import os
import sys
import tempfile
from collections import OrderedDict
from collections.abc import Callable, Hashable, Iterable, Sequence
from pathlib import Path
from typing import Any, Generic, TypeVar

import numpy as np

__all__ = ["DISABLE_VARIABLE", "RunMemo", "RunStore", "read_only"]

#: The environment variable that, set to any text that is not empty, bypasses every store.
DISABLE_VARIABLE = "NAVCORE_NO_DISK_CACHE"

T = TypeVar("T")
A = TypeVar("A")


def _array_fields(kind: type, argument: str) -> tuple[str, ...]:
    """The field names of the dataclass ``kind``; ``ValueError`` naming ``argument`` otherwise."""
    if not (isinstance(kind, type) and dataclasses.is_dataclass(kind)):
        raise ValueError(f"{argument} must be a dataclass type, got {kind!r}")
    return tuple(f.name for f in dataclasses.fields(kind))


def _check_label(label: object) -> None:
    """``ValueError`` unless ``label`` is one path component (a file name's readable prefix)."""
    if not isinstance(label, str) or not label or Path(label).name != label:
        raise ValueError(f"label must be one path component, got {label!r}")


def _check_key(key: object, argument: str) -> str:
    """``key`` itself if it is a str; ``TypeError`` naming ``argument`` otherwise."""
    if not isinstance(key, str):
        raise TypeError(f"{argument} must give a str, got {type(key).__name__}")
    return key


def _positive_int(value: object, argument: str) -> int:
    """``value`` if it is a positive int (not a bool); ``TypeError``/``ValueError`` naming ``argument``."""
    if not isinstance(value, int) or isinstance(value, bool):
        raise TypeError(f"{argument} must be an int, got {type(value).__name__}")
    if value < 1:
        raise ValueError(f"{argument} must be at least 1, got {value}")
    return value


def read_only(result: T) -> T:
    """A run with its arrays made read-only (in place), for sharing among callers.

    Parameters
    ----------
    result : dataclass instance
        A run whose fields are numpy arrays.

    Returns
    -------
    dataclass instance
        ``result`` itself.

    Raises
    ------
    ValueError
        If ``result`` is not a dataclass instance or a field is not a numpy array.

    Examples
    --------
    >>> import dataclasses
    >>> @dataclasses.dataclass
    ... class Run:
    ...     x: np.ndarray
    >>> read_only(Run(x=np.ones(2))).x.flags.writeable
    False
    """
    names = _array_fields(type(result), "result")
    for name in names:
        value = getattr(result, name)
        if not isinstance(value, np.ndarray):
            raise ValueError(f"result field {name!r} must be a numpy array, got {type(value).__name__}")
        value.flags.writeable = False
    return result


@dataclasses.dataclass(frozen=True)
class RunStore:
    """Runs of one model kept on disk, each under a key hashed from the code and the arguments.

    Parameters
    ----------
    name : str
        The store's directory, one path component (``"navcore-kzl-mc"``).
    modules : sequence of str
        Full names of the modules whose sources the runs depend on (the model's modules and
        the module that assembles the run's arguments); they are imported when a key is made.
    root : Path or None, optional
        The directory that holds the store's directory; ``None`` is the system temporary
        directory (``tempfile.gettempdir()``).

    Raises
    ------
    ValueError
        If ``name`` is empty or not one path component, or ``modules`` is empty.
    """

    name: str
    modules: Sequence[str]
    root: Path | None = None

    def __post_init__(self) -> None:
        if not self.name or Path(self.name).name != self.name or self.name in (".", ".."):
            raise ValueError(f"name must be one path component, got {self.name!r}")
        if isinstance(self.modules, str) or not self.modules:
            raise ValueError(f"modules must be a non-empty sequence of module names, got {self.modules!r}")
        object.__setattr__(self, "modules", tuple(self.modules))

    def key(self, run_key: str) -> str:
        """The hash of a run's key with the sources it depends on (24 hex digits).

        Parameters
        ----------
        run_key : str
            Text that holds every argument of the run (two runs with equal keys are equal).

        Returns
        -------
        str
            SHA-256 over the sources of ``modules`` (in their order), this module's source,
            and ``run_key`` with numpy's version; its first 24 hex digits.
        """
        if not isinstance(run_key, str):
            raise ValueError(f"run_key must be a str, got {type(run_key).__name__}")
        h = hashlib.sha256()
        for name in self.modules:
            h.update(inspect.getsource(importlib.import_module(name)).encode())
        h.update(inspect.getsource(sys.modules[__name__]).encode())
        h.update(repr((run_key, np.__version__)).encode())
        return h.hexdigest()[:24]

    def path(self, run_key: str, label: str) -> Path | None:
        """Where the run of ``run_key`` is kept, or ``None`` with the stores bypassed.

        Parameters
        ----------
        run_key : str
            The run's key (see :meth:`key`).
        label : str
            A readable prefix of the file's name (``"tc-True"``); not part of the key.

        Returns
        -------
        Path or None
            ``<root>/<name>/<label>-<key>.npz``; ``None`` when :data:`DISABLE_VARIABLE` is set.
        """
        _check_label(label)
        if os.environ.get(DISABLE_VARIABLE):
            return None
        root = Path(tempfile.gettempdir()) if self.root is None else Path(self.root)
        return root / self.name / f"{label}-{self.key(run_key)}.npz"

    def read(self, run_key: str, label: str, kind: type[T]) -> T | None:
        """The stored run of ``run_key``, read-only, or ``None`` (not stored, or bypassed).

        Parameters
        ----------
        run_key, label : str
            As for :meth:`path`.
        kind : type
            The run's dataclass; every field is read from the file.

        Returns
        -------
        kind or None
        """
        names = _array_fields(kind, "kind")
        path = self.path(run_key, label)
        if path is None or not path.exists():
            return None
        with np.load(path) as data:
            fields: dict[str, Any] = {name: data[name] for name in names}
        return read_only(kind(**fields))

    def write(self, run_key: str, label: str, result: T) -> T:
        """Keep ``result`` on disk (unless bypassed) and return it read-only.

        The file is written under a temporary name and renamed, so that a reader in another
        process never sees it half written.

        Parameters
        ----------
        run_key, label : str
            As for :meth:`path`.
        result : dataclass instance
            The run; its fields are numpy arrays.

        Returns
        -------
        dataclass instance
            ``result``, its arrays read-only.
        """
        names = _array_fields(type(result), "result")
        path = self.path(run_key, label)
        if path is not None:
            path.parent.mkdir(parents=True, exist_ok=True)
            tmp = path.with_suffix(f".{os.getpid()}.npz")
            np.savez(tmp, **{name: getattr(result, name) for name in names})
            os.replace(tmp, path)
        return read_only(result)

    def read_or_run(self, run_key: str, label: str, kind: type[T], run: Callable[[], T]) -> T:
        """The stored run of ``run_key``, or ``run()`` stored (a miss, or the stores bypassed).

        Parameters
        ----------
        run_key, label : str
            As for :meth:`path`.
        kind : type
            The run's dataclass.
        run : callable
            Computes the run (called with no argument, only on a miss).

        Returns
        -------
        kind
            The run, its arrays read-only.
        """
        stored = self.read(run_key, label, kind)
        if stored is not None:
            return stored
        return self.write(run_key, label, run())


class RunMemo(Generic[T]):
    """The runs made or read in this process, the most recently used kept, before a :class:`RunStore`.

    A run is looked up by its key (text that holds every argument of the run, as for
    :meth:`RunStore.key`) first among the runs kept here, then in ``store``, and only then
    computed; a computed run is written to ``store``, and every run found or made is kept here.
    At most ``size`` runs are kept: keeping one more forgets the least recently used (a run is
    used when it is kept, and when a lookup finds it here).

    Parameters
    ----------
    store : RunStore
        Where runs are kept between processes (bypassed by :data:`DISABLE_VARIABLE`, while this
        memo still keeps runs).
    kind : type
        The runs' dataclass (fields all numpy arrays), as for :meth:`RunStore.read`.
    size : int, optional
        Most runs kept in memory; at least 1.

    Attributes
    ----------
    store : RunStore
    kind : type
    size : int
        As given.

    Raises
    ------
    TypeError
        If ``store`` is not a :class:`RunStore` or ``size`` is not an int.
    ValueError
        If ``kind`` is not a dataclass type or ``size`` is below 1.

    Examples
    --------
    >>> import dataclasses, tempfile
    >>> @dataclasses.dataclass
    ... class Run:
    ...     x: np.ndarray
    >>> store = RunStore("doc-memo", modules=("navcore.units",), root=Path(tempfile.mkdtemp()))
    >>> memo = RunMemo(store, Run, size=2)
    >>> memo.get_or_run("seed=1", "demo", lambda: Run(x=np.zeros(2))).x.tolist()
    [0.0, 0.0]
    >>> calls = []
    >>> def run_batch(seeds):
    ...     calls.append(list(seeds))
    ...     return [Run(x=np.full(2, float(s))) for s in seeds]
    >>> runs = memo.get_or_run_batched(
    ...     [1, 2, 3], key=lambda s: f"seed={s}", label=lambda s: "demo", group=lambda s: 0,
    ...     rows=lambda s: 1, run_batch=run_batch, rows_per_call=1)
    >>> [float(run.x[0]) for run in runs], calls, memo.keys()
    ([0.0, 2.0, 3.0], [[2], [3]], ('seed=2', 'seed=3'))
    """

    def __init__(self, store: RunStore, kind: type[T], size: int = 1024) -> None:
        if not isinstance(store, RunStore):
            raise TypeError(f"store must be a RunStore, got {type(store).__name__}")
        _array_fields(kind, "kind")
        self.store = store
        self.kind = kind
        self.size = _positive_int(size, "size")
        self._runs: OrderedDict[str, T] = OrderedDict()

    def __len__(self) -> int:
        return len(self._runs)

    def __contains__(self, key: object) -> bool:
        return key in self._runs

    def keys(self) -> tuple[str, ...]:
        """The keys of the runs kept in memory, the least recently used first.

        Returns
        -------
        tuple of str
        """
        return tuple(self._runs)

    def clear(self) -> None:
        """Forget every run kept in memory (the store's files stay)."""
        self._runs.clear()

    def _recall(self, key: str) -> T | None:
        """The run of ``key`` kept in memory (now the most recently used), or ``None``."""
        result = self._runs.get(key)
        if result is not None:
            self._runs.move_to_end(key)
        return result

    def _keep(self, key: str, result: T) -> T:
        """Keep ``result`` as the most recently used run, forgetting the least recently used ones
        beyond :attr:`size`; return it."""
        self._runs[key] = result
        self._runs.move_to_end(key)
        while len(self._runs) > self.size:
            self._runs.popitem(last=False)
        return result

    def get_or_run(self, key: str, label: str, run: Callable[[], T]) -> T:
        """The run of ``key``: kept in memory, else stored on disk, else ``run()`` (then stored).

        Parameters
        ----------
        key : str
            The run's key (every argument of the run).
        label : str
            A readable prefix of the run's file name in the store (:meth:`RunStore.path`).
        run : callable
            Computes the run (called with no argument, only when neither memory nor disk holds it).

        Returns
        -------
        kind
            The run, its arrays read-only when it comes from the store or was computed here.

        Raises
        ------
        TypeError
            If ``key`` is not a str or ``run`` is not callable.
        ValueError
            If ``label`` is not one path component.
        """
        _check_key(key, "key")
        _check_label(label)
        if not callable(run):
            raise TypeError(f"run must be callable, got {type(run).__name__}")
        result = self._recall(key)
        if result is None:
            result = self._keep(key, self.store.read_or_run(key, label, self.kind, run))
        return result

    def get_or_run_batched(
        self,
        items: Iterable[A],
        *,
        key: Callable[[A], str],
        label: Callable[[A], str],
        group: Callable[[A], Hashable],
        rows: Callable[[A], int],
        run_batch: Callable[[list[A]], Sequence[T]],
        rows_per_call: int,
    ) -> list[T]:
        """The runs of many items, those that neither memory nor disk holds made in batched calls.

        Each item (one run's arguments) is looked up in turn by its key, first in memory, then
        on disk (a run read from disk is kept in memory). The items left, one per key (the first
        item of a repeated key), are grouped by ``group`` (the items that one call of
        ``run_batch`` can take together), in the order of their first item; each group is split,
        in order, into calls of at most ``rows_per_call`` rows (an item of more rows is a call of
        its own). Every run made is written to the store and kept in memory.

        Parameters
        ----------
        items : iterable
            The runs' arguments, any objects the callables below read.
        key : callable
            ``key(item)``: the run's key (str).
        label : callable
            ``label(item)``: the readable prefix of the run's file name (one path component).
        group : callable
            ``group(item)``: a hashable value, equal for the items ``run_batch`` can take in
            one call.
        rows : callable
            ``rows(item)``: the item's share of one call's size (a positive int: the Monte
            Carlo runs of a scenario, for instance).
        run_batch : callable
            ``run_batch(chunk)``: the runs of a list of items of one group, in order.
        rows_per_call : int
            Most rows of one call of ``run_batch`` (at least 1).

        Returns
        -------
        list
            The run of each item, in the order of ``items``.

        Raises
        ------
        TypeError
            If ``key`` gives a value that is not a str, or ``rows`` or ``rows_per_call`` is
            not an int.
        ValueError
            If ``rows_per_call`` or a value of ``rows`` is below 1, ``label`` gives a value
            that is not one path component, or ``run_batch`` returns another number of runs
            than it was given items.
        """
        _positive_int(rows_per_call, "rows_per_call")
        found: dict[str, T] = {}
        order: list[str] = []
        waiting: dict[Hashable, dict[str, tuple[A, str, int]]] = {}
        queued: set[str] = set()
        for item in items:
            k = _check_key(key(item), "key")
            order.append(k)
            if k in found or k in queued:
                continue
            result = self._recall(k)
            if result is None:
                name = label(item)
                _check_label(name)
                result = self.store.read(k, name, self.kind)
                if result is None:
                    size = _positive_int(rows(item), "rows")
                    waiting.setdefault(group(item), {})[k] = (item, name, size)
                    queued.add(k)
                    continue
                self._keep(k, result)
            found[k] = result
        for members in waiting.values():
            for chunk in _split_rows(members, rows_per_call):
                results = list(run_batch([members[k][0] for k in chunk]))
                if len(results) != len(chunk):
                    raise ValueError(
                        f"run_batch must return one run per item: {len(chunk)} items, {len(results)} runs"
                    )
                for k, result in zip(chunk, results, strict=True):
                    found[k] = self._keep(k, self.store.write(k, members[k][1], result))
        return [found[k] for k in order]


def _split_rows(members: dict[str, tuple[Any, str, int]], rows_per_call: int) -> list[list[str]]:
    """The keys of ``members`` (each with its item, label and rows), in order, split into lists of
    at most ``rows_per_call`` rows (a key of more rows alone)."""
    chunks: list[list[str]] = []
    chunk: list[str] = []
    used = 0
    for k, (_, _, size) in members.items():
        if chunk and used + size > rows_per_call:
            chunks.append(chunk)
            chunk, used = [], 0
        chunk.append(k)
        used += size
    if chunk:
        chunks.append(chunk)
    return chunks
