"""A disk store of model runs: results made of numpy arrays, kept between processes.

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
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any, TypeVar

import numpy as np

__all__ = ["DISABLE_VARIABLE", "RunStore", "read_only"]

#: The environment variable that, set to any text that is not empty, bypasses every store.
DISABLE_VARIABLE = "NAVCORE_NO_DISK_CACHE"

T = TypeVar("T")


def _array_fields(kind: type, argument: str) -> tuple[str, ...]:
    """The field names of the dataclass ``kind``; ``ValueError`` naming ``argument`` otherwise."""
    if not (isinstance(kind, type) and dataclasses.is_dataclass(kind)):
        raise ValueError(f"{argument} must be a dataclass type, got {kind!r}")
    return tuple(f.name for f in dataclasses.fields(kind))


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
        if not label or Path(label).name != label:
            raise ValueError(f"label must be one path component, got {label!r}")
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
