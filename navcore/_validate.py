"""Input validation shared by the models.

Every check raises ``ValueError`` whose message names the parameter and the constraint, so
that a bad input fails where it enters instead of travelling on as a NaN.
"""

from __future__ import annotations

import functools
import inspect
import math
from collections.abc import Callable
from typing import Any, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "MAX_LOOP_COUNT",
    "as_finite_array",
    "check_argument",
    "check_public",
    "checked",
    "require_finite",
    "require_in_range",
    "require_integer",
    "require_nonnegative",
    "require_positive",
    "require_probability",
    "require_square",
    "require_symmetric_psd",
]

_R = TypeVar("_R")


def as_finite_array(name: str, value: ArrayLike, *, ndim: int | None = None) -> NDArray[np.float64]:
    """Return ``value`` as a float array, checking that every element is finite."""
    arr = np.asarray(value, dtype=float)
    if ndim is not None and arr.ndim != ndim:
        raise ValueError(f"{name} must be a {ndim}-dimensional array, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite (no NaN or infinity), got {value!r}")
    return arr


def require_finite(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """Check that ``value`` is finite everywhere and return it as an array."""
    return as_finite_array(name, value)


def require_positive(name: str, value: ArrayLike, *, allow_inf: bool = False) -> Any:
    """Check ``value > 0`` everywhere (and finite unless ``allow_inf``)."""
    arr = np.asarray(value, dtype=float)
    if np.any(np.isnan(arr)) or np.any(arr <= 0) or (not allow_inf and np.any(np.isinf(arr))):
        bound = "> 0" if allow_inf else "> 0 and finite"
        raise ValueError(f"{name} must be {bound}, got {value!r}")
    return value


def require_nonnegative(name: str, value: ArrayLike, *, allow_inf: bool = False) -> Any:
    """Check ``value >= 0`` everywhere (and finite unless ``allow_inf``)."""
    arr = np.asarray(value, dtype=float)
    if np.any(np.isnan(arr)) or np.any(arr < 0) or (not allow_inf and np.any(np.isinf(arr))):
        bound = ">= 0" if allow_inf else ">= 0 and finite"
        raise ValueError(f"{name} must be {bound}, got {value!r}")
    return value


def require_probability(name: str, value: ArrayLike, *, open_interval: bool = False) -> Any:
    """Check ``0 <= value <= 1`` (or ``0 < value < 1`` with ``open_interval``)."""
    arr = np.asarray(value, dtype=float)
    if open_interval:
        bad = np.any(np.isnan(arr)) or np.any(arr <= 0) or np.any(arr >= 1)
        bound = "in the open interval (0, 1)"
    else:
        bad = np.any(np.isnan(arr)) or np.any(arr < 0) or np.any(arr > 1)
        bound = "in [0, 1]"
    if bad:
        raise ValueError(f"{name} must be a probability {bound}, got {value!r}")
    return value


def require_in_range(name: str, value: ArrayLike, low: float, high: float) -> Any:
    """Check ``low <= value <= high`` everywhere."""
    arr = np.asarray(value, dtype=float)
    if np.any(np.isnan(arr)) or np.any(arr < low) or np.any(arr > high):
        raise ValueError(f"{name} must lie in [{low}, {high}], got {value!r}")
    return value


def require_integer(name: str, value: Any, *, minimum: int | None = None) -> int:
    """Check that ``value`` is an integer (optionally ``>= minimum``) and return it."""
    if isinstance(value, bool) or not isinstance(value, int | np.integer):
        raise ValueError(f"{name} must be an integer, got {value!r}")
    if minimum is not None and value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value!r}")
    return int(value)


def require_square(name: str, value: ArrayLike, size: int | None = None) -> NDArray[np.float64]:
    """Check that ``value`` is a finite square matrix (of ``size`` if given)."""
    arr = as_finite_array(name, value, ndim=2)
    if arr.shape[0] != arr.shape[1]:
        raise ValueError(f"{name} must be a square matrix, got shape {arr.shape}")
    if size is not None and arr.shape[0] != size:
        raise ValueError(f"{name} must be {size}x{size}, got shape {arr.shape}")
    return arr


def require_symmetric_psd(
    name: str, value: ArrayLike, *, rtol: float = 1e-9, definite: bool = False
) -> NDArray[np.float64]:
    """Check that ``value`` is a symmetric positive semi-definite (or definite) matrix.

    Symmetry is tested relative to the matrix scale; the eigenvalue test allows a round-off
    margin of ``rtol`` times the largest eigenvalue.
    """
    arr = require_square(name, value)
    scale = max(float(np.max(np.abs(arr))), np.finfo(float).tiny)
    if np.max(np.abs(arr - arr.T)) > rtol * scale * 10:
        raise ValueError(f"{name} must be symmetric")
    eig = np.linalg.eigvalsh(0.5 * (arr + arr.T))
    floor = -rtol * max(float(eig[-1]), 0.0) if eig.size else 0.0
    if definite and (eig.size and eig[0] <= 0):
        raise ValueError(f"{name} must be positive definite (smallest eigenvalue {eig[0]:.3g})")
    if eig.size and eig[0] < floor:
        raise ValueError(f"{name} must be positive semi-definite (smallest eigenvalue {eig[0]:.3g})")
    return arr


# --------------------------------------------------------------------------------------------
# Checking at the boundary from the annotations
# --------------------------------------------------------------------------------------------
#: Largest number of steps, samples or iterations a caller's argument may ask a loop for; a
#: bigger request is almost always a unit or typo error (``1e8`` for ``1e3``), and would run
#: for minutes. Functions with such a loop check their count against this bound and say so.
MAX_LOOP_COUNT = 10_000_000

_NUMBER = "number"
_INTEGER = "integer"
_ARRAY = "array"


def _kind(annotation: object) -> tuple[str | None, bool]:
    """Classify a (string) annotation: ("number"|"integer"|"array"|None, None allowed)."""
    text = str(annotation if isinstance(annotation, str) else getattr(annotation, "__name__", ""))
    if "[" in text.replace("NDArray[", "").replace("np.dtype[", ""):
        return None, False  # a container (Sequence[...], dict[...]): the function checks it
    parts = {p.strip() for p in text.split("|")}
    allows_none = "None" in parts
    parts.discard("None")
    if any(("ArrayLike" in p or "NDArray" in p or p in {"Array", "np.ndarray"}) for p in parts):
        return _ARRAY, allows_none
    if parts and parts <= {"float", "int", "np.floating", "np.integer"} and "float" in parts:
        return _NUMBER, allows_none
    if parts == {"int"}:
        return _INTEGER, allows_none
    return None, allows_none


def check_argument(name: str, value: Any, kind: str, *, allow_inf: bool = False) -> None:
    """Check one argument of the given kind (see :func:`checked`); raise naming ``name``."""
    if kind == _INTEGER:
        if isinstance(value, bool) or not isinstance(value, int | np.integer):
            raise TypeError(f"{name} must be an integer, got {value!r}")
        return
    if kind == _NUMBER:
        if isinstance(value, bool) or not isinstance(value, int | float | np.integer | np.floating):
            if isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf":
                value = value.item()
            else:
                raise TypeError(f"{name} must be a real number, got {value!r}")
        if value != value or (not allow_inf and value in (math.inf, -math.inf)):
            raise ValueError(f"{name} must be finite (no NaN or infinity), got {value!r}")
        return
    # array: anything numpy turns into a numeric array
    if isinstance(value, str | bytes) or value is None:
        raise TypeError(f"{name} must be a number or an array of numbers, got {value!r}")
    try:
        arr = np.asarray(value)
    except ValueError as exc:  # ragged nested sequences
        raise ValueError(f"{name} must be a rectangular array of numbers ({exc})") from None
    if arr.dtype.kind not in "biufc":
        raise TypeError(f"{name} must be a number or an array of numbers, got dtype {arr.dtype}")
    if arr.dtype.kind in "fc":
        ok = np.isfinite(arr) if not allow_inf else ~np.isnan(arr)
        if not ok.all():
            what = "NaN" if allow_inf else "NaN or infinity"
            raise ValueError(f"{name} must be finite (no {what})")


def checked(
    func: Callable[..., _R] | None = None,
    *,
    allow_inf: tuple[str, ...] = (),
    skip: tuple[str, ...] = (),
) -> Any:
    """Decorator: check every numeric argument of ``func`` against its annotation.

    A parameter annotated ``float`` must be a real number and finite; ``int`` an integer
    (not ``bool``); ``ArrayLike``/``NDArray`` anything numpy turns into a numeric,
    rectangular array, finite everywhere. ``None`` passes where the annotation allows it.
    ``allow_inf`` lists parameters for which infinity is a meaningful value; ``skip`` lists
    parameters left to the function's own checks. Range and shape constraints stay in the
    function body: this only makes the generic failures (NaN, infinity, a string, a ragged
    list) raise a ``TypeError``/``ValueError`` that names the parameter as the caller
    spelled it.
    """

    def wrap(f: Callable[..., _R]) -> Callable[..., _R]:
        sig = inspect.signature(f)
        specs: list[tuple[int | None, str, str, bool, bool]] = []
        for i, p in enumerate(sig.parameters.values()):
            if p.name in skip or p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
                continue
            kind, allows_none = _kind(p.annotation)
            if kind is None:
                continue
            pos = i if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD) else None
            specs.append((pos, p.name, kind, allows_none, p.name in allow_inf))
        if not specs:
            return f

        @functools.wraps(f)
        def wrapper(*args: Any, **kwargs: Any) -> _R:
            if kwargs.get("validate", True) is False:  # the caller checked at its boundary
                return f(*args, **kwargs)
            n = len(args)
            for pos, name, kind, allows_none, inf_ok in specs:
                if pos is not None and pos < n:
                    value = args[pos]
                elif name in kwargs:
                    value = kwargs[name]
                else:
                    continue  # the default, or a missing argument Python reports itself
                if value is None and allows_none:
                    continue
                check_argument(name, value, kind, allow_inf=inf_ok)
            return f(*args, **kwargs)

        wrapper.__navcore_checked__ = True  # type: ignore[attr-defined]
        return wrapper

    return wrap(func) if func is not None else wrap


def check_public(namespace: dict[str, Any], **options: dict[str, tuple[str, ...]]) -> None:
    """Wrap every public function of a module (its ``__all__``) with :func:`checked`.

    Called once at the end of a model module: ``check_public(globals())``. Keyword
    arguments map a function name to its ``checked`` options, e.g.
    ``check_public(globals(), chernoff_log_tail={"allow_inf": ("t",)})``.
    """
    for name in namespace.get("__all__", ()):
        obj = namespace[name]
        if inspect.isfunction(obj) and not getattr(obj, "__navcore_checked__", False):
            namespace[name] = checked(obj, **options.get(name, {}))
