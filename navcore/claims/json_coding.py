"""JSON coding of the values a claim computes: numbers, truth values and arrays, there and back.

The one encoding the ledger's JSON, its cache and its exports share: :func:`jsonable` turns a
value (numpy scalars and arrays, tuples, non-finite floats) into JSON-ready data, and
:func:`from_jsonable` reads it back.
"""

from __future__ import annotations

import math
from typing import Any

__all__ = ["from_jsonable", "jsonable"]


def _json_number(value: Any, *, round_trip: bool = False) -> Any:
    """A number as JSON: a float; a non-finite one as text (``"Infinity"``, ``"-Infinity"``,
    ``None`` for NaN) or, for a round trip, as ``{"float": "inf"}`` (:func:`from_jsonable`)."""
    v = float(value)
    if math.isfinite(v):
        return v
    if round_trip:
        return {"float": repr(v)}
    return None if math.isnan(v) else ("Infinity" if v > 0 else "-Infinity")


def _json_value(value: Any) -> Any:
    """A claim's value as its JSON record holds it: a truth value or ``None`` as it is, any
    other value as a float (:func:`_json_number`)."""
    if value is None or isinstance(value, bool):
        return value
    return _json_number(value)


def jsonable(value: Any, *, round_trip: bool = False) -> Any:
    """A value as plain JSON (numbers, strings, lists, objects): the ledger's one JSON encoder.

    For a reader (the export, the input records, the tools' records): a numpy value or array
    as the Python value or list it holds, a key as text, a non-finite number as text, anything
    else as its ``repr``. For a round trip (``round_trip=True``, the registry's stored
    evaluations, read back by :func:`from_jsonable`): keys, integers and truth values as they
    are, every other number as a float with a non-finite one kept exactly; a value that is no
    number raises.

    Parameters
    ----------
    value : Any
        The value: ``None``, a truth value, text, a number (numpy's too), an array, or a list,
        tuple or dict of them.
    round_trip : bool, optional
        Code it so that :func:`from_jsonable` gives it back (``False``: for a reader).

    Returns
    -------
    Any
        The value as JSON-ready data.

    Raises
    ------
    TypeError, ValueError
        With ``round_trip=True``, for a value that is no number, text, truth value or
        container of them.

    Examples
    --------
    >>> import numpy as np
    >>> jsonable({1: np.float64(0.5), "a": (np.int64(2), float("inf"))})
    {'1': 0.5, 'a': [2, 'Infinity']}
    >>> jsonable((0.5, float("inf")), round_trip=True)
    [0.5, {'float': 'inf'}]
    """
    if value is None or isinstance(value, bool | str | int):
        return value
    if isinstance(value, dict):
        return {(k if round_trip else str(k)): jsonable(v, round_trip=round_trip) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [jsonable(v, round_trip=round_trip) for v in value]
    if round_trip:
        return _json_number(value, round_trip=True)
    if not isinstance(value, float) and hasattr(value, "tolist"):
        return jsonable(value.tolist())
    try:
        return _json_number(value)
    except (TypeError, ValueError):
        return repr(value)


def from_jsonable(value: Any, sequence: type = tuple) -> Any:
    """Undo :func:`jsonable` with ``round_trip=True``; JSON arrays become ``sequence`` (tuples,
    as the evaluation fields hold them; the recorded input values are plain JSON with lists).

    Parameters
    ----------
    value : Any
        JSON data as :func:`jsonable` coded it with ``round_trip=True``.
    sequence : type, optional
        What a JSON array becomes (``tuple`` by default, ``list`` for plain JSON).

    Returns
    -------
    Any
        The value coded.

    Examples
    --------
    >>> from_jsonable([0.5, {"float": "inf"}, {"k": [1, 2]}])
    (0.5, inf, {'k': (1, 2)})
    >>> from_jsonable([1, [2]], list)
    [1, [2]]
    """
    if isinstance(value, dict):
        if set(value) == {"float"}:
            return float(value["float"])
        return {k: from_jsonable(v, sequence) for k, v in value.items()}
    if isinstance(value, list):
        return sequence(from_jsonable(v, sequence) for v in value)
    return value
