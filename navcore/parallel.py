"""One executor interface for navcore's independent tasks: ledger claims and Monte Carlo batches.

Every parallel loop of navcore goes through :func:`run_tasks`, a thin layer over joblib: the
tasks run in the calling process (``n_jobs=None`` or ``1``), in worker processes on this
machine (joblib's default loky backend, ``n_jobs=-1`` for every core), or on a dask cluster
(joblib's ``dask`` backend, selected by the caller with ``joblib.parallel_config``). The
results come back in the order of the tasks whatever ran where, and every task draws its
random numbers from its own seed (:func:`task_seeds`), so serial, parallel and dask runs give
the same numbers bit for bit.

Examples
--------
>>> run_tasks(pow, [(2, 3), (3, 2), (10, 0)])
[8, 9, 1]

On a dask cluster (``pip install navcore[dask]``), the same call inside joblib's context:

>>> from distributed import Client, LocalCluster  # doctest: +SKIP
>>> import joblib  # doctest: +SKIP
>>> with LocalCluster(n_workers=2) as cluster, Client(cluster):  # doctest: +SKIP
...     with joblib.parallel_config(backend="dask"):
...         run_tasks(pow, [(2, 3), (3, 2)], n_jobs=-1)
[8, 9]
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Sequence
from typing import Any, TypeVar

import numpy as np

__all__ = ["effective_jobs", "run_tasks", "task_seeds"]

R = TypeVar("R")


def effective_jobs(n_jobs: int | None) -> int:
    """The number of workers ``n_jobs`` asks for on this machine (joblib's convention).

    Parameters
    ----------
    n_jobs : int or None
        ``None``, ``0`` or ``1``: one (the calling process); ``k > 1``: ``k``; ``-1``: every
        core, ``-2`` every core but one, and so on.

    Returns
    -------
    int
        At least 1.

    Raises
    ------
    TypeError
        If ``n_jobs`` is not an integer or ``None``.

    Examples
    --------
    >>> effective_jobs(None), effective_jobs(3), effective_jobs(-1) == (os.cpu_count() or 1)
    (1, 3, True)
    """
    if n_jobs is None:
        return 1
    if isinstance(n_jobs, bool) or not isinstance(n_jobs, int | np.integer):
        raise TypeError(f"n_jobs must be an integer or None, got {n_jobs!r}")
    if n_jobs < 0:
        return max(1, (os.cpu_count() or 1) + 1 + int(n_jobs))
    return max(1, int(n_jobs))


def run_tasks(
    function: Callable[..., R],
    tasks: Iterable[Sequence[Any]],
    *,
    n_jobs: int | None = None,
) -> list[R]:
    """Run ``function(*task)`` for every task and return the results in the order of the tasks.

    Parameters
    ----------
    function : callable
        A module-level function (it is sent to worker processes by reference, with its
        arguments pickled).
    tasks : iterable of sequences
        The positional arguments of each call.
    n_jobs : int or None, optional
        ``None`` or ``1``: every call in this process, one after another, without joblib;
        otherwise joblib's ``Parallel(n_jobs=n_jobs)`` with whatever backend the caller's
        ``joblib.parallel_config`` selects (loky processes by default, ``"dask"`` for a dask
        cluster). Tasks are handed out one at a time in the given order, so put the longest
        first.

    Returns
    -------
    list
        ``[function(*task) for task in tasks]``, whatever ran where.

    Examples
    --------
    >>> run_tasks(divmod, [(7, 2), (9, 4)], n_jobs=1)
    [(3, 1), (2, 1)]
    """
    work = [tuple(task) for task in tasks]
    if effective_jobs(n_jobs) == 1 and n_jobs in (None, 0, 1):
        return [function(*task) for task in work]
    import joblib

    parallel = joblib.Parallel(n_jobs=n_jobs, batch_size=1, pre_dispatch="all")
    return list(parallel(joblib.delayed(function)(*task) for task in work))


def task_seeds(seed: int, n_tasks: int) -> list[np.random.SeedSequence]:
    """Independent seeds for ``n_tasks`` tasks of one seeded computation.

    The children of ``numpy.random.SeedSequence(seed)``: task ``i`` gets the same stream
    whichever worker runs it and however many workers there are.

    Parameters
    ----------
    seed : int
        The computation's seed (>= 0).
    n_tasks : int
        Number of tasks (>= 1).

    Returns
    -------
    list of numpy.random.SeedSequence
        One per task; ``numpy.random.default_rng(s)`` turns each into a generator.

    Raises
    ------
    ValueError
        If ``seed`` is negative or ``n_tasks`` is below 1.

    Examples
    --------
    >>> a = [np.random.default_rng(s).integers(100) for s in task_seeds(7, 3)]
    >>> b = [np.random.default_rng(s).integers(100) for s in task_seeds(7, 3)]
    >>> a == b, len(set(a)) > 1
    (True, True)
    """
    if isinstance(seed, bool) or not isinstance(seed, int | np.integer) or seed < 0:
        raise ValueError(f"seed must be an integer >= 0, got {seed!r}")
    if isinstance(n_tasks, bool) or not isinstance(n_tasks, int | np.integer) or n_tasks < 1:
        raise ValueError(f"n_tasks must be an integer >= 1, got {n_tasks!r}")
    return list(np.random.SeedSequence(int(seed)).spawn(int(n_tasks)))
