"""Input validation shared by the models.

Every check raises ``ValueError`` whose message names the parameter and the constraint, so
that a bad input fails where it enters instead of travelling on as a NaN.
"""

from __future__ import annotations

import ast
import builtins
import dataclasses
import functools
import inspect
import math
from collections.abc import Callable
from typing import Any, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "COUNT",
    "COUNT0",
    "MAX_LOOP_COUNT",
    "NONNEGATIVE",
    "OPEN_PROBABILITY",
    "POSITIVE",
    "PROBABILITY",
    "Range",
    "as_finite_array",
    "check_argument",
    "check_public",
    "check_symmetric_psd",
    "checked",
    "require_finite",
    "require_in_range",
    "require_integer",
    "require_nonnegative",
    "require_positive",
    "require_probability",
    "require_square",
    "require_symmetric_psd",
    "unchecked",
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
    check_symmetric_psd(name, arr, rtol=rtol, definite=definite)
    return arr


def check_symmetric_psd(
    name: str, arr: NDArray[np.float64], *, rtol: float = 1e-9, definite: bool = False
) -> None:
    """:func:`require_symmetric_psd` for a float square matrix already checked finite.

    The common case costs one Cholesky factorisation: a matrix whose factorisation succeeds
    after a shift of ``rtol`` times its largest diagonal element (no larger than its largest
    eigenvalue) passes the eigenvalue test too (for ``definite``: unshifted, every pivot
    well above round-off); any other matrix goes to that test (``eigvalsh``), which decides
    and words the error as before.
    """
    scale = max(float(np.abs(arr).max()), _TINY)
    diff = arr - arr.T
    if float(np.abs(diff, out=diff).max()) > rtol * scale * 10:
        raise ValueError(f"{name} must be symmetric")
    n = arr.shape[0]
    top = float(arr.diagonal().max())  # the symmetric part has the same diagonal
    if top > 0:
        shifted = arr + arr.T
        shifted *= 0.5  # the symmetric part, as below
        if not definite:
            shifted.flat[:: n + 1] += rtol * top
        lower, info = _potrf(shifted)
        if info == 0 and (not definite or float(lower.diagonal().min()) ** 2 > _SQRT_EPS * top):
            return  # positive (semi-)definite within the margin of the eigenvalue test
    eig = np.linalg.eigvalsh(0.5 * (arr + arr.T))
    floor = -rtol * max(float(eig[-1]), 0.0) if eig.size else 0.0
    if definite and (eig.size and eig[0] <= 0):
        raise ValueError(f"{name} must be positive definite (smallest eigenvalue {eig[0]:.3g})")
    if eig.size and eig[0] < floor:
        raise ValueError(f"{name} must be positive semi-definite (smallest eigenvalue {eig[0]:.3g})")


_TINY = float(np.finfo(float).tiny)
_SQRT_EPS = float(np.sqrt(np.finfo(float).eps))
_DPOTRF: Any = None


def _potrf(a: NDArray[np.float64]) -> tuple[NDArray[np.float64], int]:
    """LAPACK's Cholesky factorisation of ``a`` (overwritten): (lower factor, info > 0 on failure)."""
    global _DPOTRF
    if _DPOTRF is None:
        from scipy.linalg import lapack

        _DPOTRF = lapack.dpotrf
    lower, info = _DPOTRF(a, lower=1, clean=0, overwrite_a=1)
    return lower, int(info)


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
    if any(("ArrayLike" in p or "NDArray" in p or p in {"Array", "FloatArray", "np.ndarray"}) for p in parts):
        return _ARRAY, allows_none
    if parts and parts <= {"float", "int", "np.floating", "np.integer"} and "float" in parts:
        return _NUMBER, allows_none
    if parts == {"int"}:
        return _INTEGER, allows_none
    return None, allows_none


def _classes(annotation: object, namespace: dict[str, Any]) -> tuple[type, ...] | None:
    """The classes a (string) annotation names, if it is a class or a union of classes.

    ``"ImuSpec"``, ``"StateLayout | None"``, ``"np.random.Generator | int | None"``;
    ``int``/``float``/``str`` members are kept as themselves; anything generic
    (``Sequence[...]``, ``Callable``) returns None and is left to the function.
    """
    if not isinstance(annotation, str) or "[" in annotation or annotation == "Any":
        return None
    classes: list[type] = []
    for part in annotation.split("|"):
        part = part.strip()
        if part == "None":
            classes.append(type(None))
            continue
        head = part.split(".")[0]
        obj: Any = namespace.get(head, getattr(builtins, head, None))
        for attr in part.split(".")[1:]:
            obj = getattr(obj, attr, None)
        if not isinstance(obj, type) or obj.__module__ in ("typing", "collections.abc"):
            return None
        if getattr(obj, "_is_protocol", False) and not getattr(obj, "_is_runtime_protocol", False):
            return None  # a static protocol: isinstance cannot check it
        if obj is bool:
            classes += [bool, np.bool_]
        elif obj is float:
            classes += [float, int, np.floating, np.integer]
        elif obj is int:
            classes.append(np.integer)
            classes.append(int)
        else:
            classes.append(obj)
    return tuple(classes) or None


@dataclasses.dataclass(frozen=True)
class Range:
    """An interval a numeric argument must lie in (every element of an array).

    ``low``/``high`` are the bounds (None: unbounded); ``low_open``/``high_open`` exclude
    them. Used by :func:`checked` through its ``ranges`` option.
    """

    low: float | None = None
    high: float | None = None
    low_open: bool = False
    high_open: bool = False

    def describe(self) -> str:
        if self.high is None and self.low is not None:
            return f"{'>' if self.low_open else '>='} {self.low:g}"
        if self.low is None and self.high is not None:
            return f"{'<' if self.high_open else '<='} {self.high:g}"
        lo = "(" if self.low_open else "["
        hi = ")" if self.high_open else "]"
        return f"in {lo}{self.low:g}, {self.high:g}{hi}"

    def check(self, name: str, value: Any) -> None:
        arr = np.asarray(value)
        if arr.dtype.kind not in "biuf" or arr.size == 0:
            return
        bad = np.isnan(arr) if arr.dtype.kind == "f" else np.zeros(arr.shape, bool)
        if self.low is not None:
            bad |= (arr <= self.low) if self.low_open else (arr < self.low)
        if self.high is not None:
            bad |= (arr >= self.high) if self.high_open else (arr > self.high)
        if bad.any():
            shown = value if arr.size == 1 else f"an array with {int(bad.sum())} element(s) outside"
            raise ValueError(f"{name} must be {self.describe()}, got {shown!r}")


POSITIVE = Range(0.0, None, low_open=True)
NONNEGATIVE = Range(0.0)
PROBABILITY = Range(0.0, 1.0)
OPEN_PROBABILITY = Range(0.0, 1.0, low_open=True, high_open=True)
COUNT = Range(1, MAX_LOOP_COUNT)  # a number of steps, samples, runs, lists: bounded
COUNT0 = Range(0, MAX_LOOP_COUNT)


def _container(annotation: object, namespace: dict[str, Any]) -> list[Any] | None:
    """``Literal[...]`` -> ["literal", values]; ``Sequence[C]``/``list[C]``/``tuple[C, ...]`` of a
    class ``C`` -> ["sequence", (C,)]; anything else None."""
    if not isinstance(annotation, str):
        return None
    text = annotation.replace(" ", "")
    if text.startswith("Callable") and "|" not in text:
        return ["callable"]
    if text.startswith("Literal[") and text.endswith("]"):
        try:
            values = ast.literal_eval(f"({annotation.strip()[8:-1]},)")
        except (ValueError, SyntaxError):
            return None
        return ["literal", tuple(values)]
    for head in ("Sequence[", "list[", "tuple["):
        if text.startswith(head) and text.endswith("]"):
            inner = text[len(head) : -1].removesuffix(",...")
            classes = _classes(inner, namespace)
            if classes is None or any(c in (float, int, type(None)) for c in classes):
                return None
            return ["sequence", classes]
    return None


def _check_container(name: str, value: Any, kind: list[Any]) -> None:
    if kind[0] == "callable":
        if not callable(value):
            raise TypeError(f"{name} must be callable, got {value!r}")
        return
    if kind[0] == "literal":
        if isinstance(value, np.ndarray) or value not in kind[1]:
            raise ValueError(f"{name} must be one of {list(kind[1])}, got {value!r}")
        return
    if not isinstance(value, list | tuple):
        raise TypeError(f"{name} must be a list or tuple, got {type(value).__name__}")
    for i, item in enumerate(value):
        if not isinstance(item, kind[1]):
            expected = " or ".join(c.__name__ for c in kind[1])
            raise TypeError(f"{name}[{i}] must be of type {expected}, got {item!r}")


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
    ranges: dict[str, Range] | None = None,
) -> Any:
    """Decorator: check every numeric argument of ``func`` against its annotation.

    A parameter annotated ``float`` must be a real number and finite; ``int`` an integer
    (not ``bool``); ``ArrayLike``/``NDArray`` anything numpy turns into a numeric,
    rectangular array, finite everywhere. ``None`` passes where the annotation allows it.
    ``allow_inf`` lists parameters for which infinity is a meaningful value; ``skip`` lists
    parameters left to the function's own checks; ``ranges`` maps a parameter name to the
    :class:`Range` its value must lie in (a name the function does not have is ignored, so a
    module can state its conventions once: ``p_d`` is a probability, ``k`` a count). Shape
    constraints stay in the function body. Every failure raises a ``TypeError`` or
    ``ValueError`` that names the parameter as the caller spelled it.

    A call with ``validate=False`` (for functions that have that keyword) skips the checks.
    """

    def wrap(f: Callable[..., _R]) -> Callable[..., _R]:
        sig = inspect.signature(f)
        specs: list[tuple[int | None, str, Any, bool, bool, Range | None]] = []
        for i, p in enumerate(sig.parameters.values()):
            if p.name in skip or p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
                continue
            kind: Any
            kind, allows_none = _kind(p.annotation)
            if kind is None:
                kind = _classes(p.annotation, f.__globals__)  # a tuple of classes, or None
            if kind is None:
                kind = _container(p.annotation, f.__globals__)  # ("literal"|"sequence", ...)
                if kind is None:
                    continue
            pos = i if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD) else None
            specs.append((pos, p.name, kind, allows_none, p.name in allow_inf, (ranges or {}).get(p.name)))
        names = tuple(sig.parameters)

        @functools.wraps(f)
        def wrapper(*args: Any, **kwargs: Any) -> _R:
            if kwargs.get("validate", True) is False:  # the caller checked at its boundary
                return f(*args, **kwargs)
            n = len(args)
            for pos, name, kind, allows_none, inf_ok, interval in specs:
                if pos is not None and pos < n:
                    value = args[pos]
                elif name in kwargs:
                    value = kwargs[name]
                else:
                    continue  # the default, or a missing argument Python reports itself
                if value is None and allows_none:
                    continue
                if isinstance(kind, list):
                    _check_container(name, value, kind)
                    continue
                if isinstance(kind, tuple):
                    if not isinstance(value, kind):
                        expected = " or ".join(c.__name__ for c in kind)
                        raise TypeError(f"{name} must be of type {expected}, got {value!r}")
                    continue
                check_argument(name, value, kind, allow_inf=inf_ok)
                if interval is not None:
                    interval.check(name, value)
            try:
                return f(*args, **kwargs)
            except _SHAPE_ERRORS as exc:
                if isinstance(exc, ValueError) and (
                    not _is_numpy_shape_message(str(exc)) or _names_a_parameter(str(exc), names)
                ):
                    raise  # a navcore check, which already names the parameter
                raise ValueError(
                    f"{f.__name__}: the arguments' shapes do not fit the model "
                    f"({_shapes(sig, args, kwargs)}); see its docstring for the shapes: {exc}"
                ) from exc
            except (TypeError, AttributeError) as exc:
                if not _is_wrong_type_message(str(exc)) or _names_a_parameter(str(exc), names):
                    raise
                raise TypeError(
                    f"{f.__name__}: an argument has the wrong type ({_shapes(sig, args, kwargs)}): {exc}"
                ) from exc

        wrapper.__navcore_checked__ = True  # type: ignore[attr-defined]
        return wrapper

    return wrap(func) if func is not None else wrap


def unchecked(func: Callable[..., _R]) -> Callable[..., _R]:
    """The function that a :func:`checked` wrapper wraps (``func`` itself if it is not wrapped).

    For a loop that checked its arguments once at its boundary and calls a public kernel at
    every step: the same function, without the argument checks (and without the wrapper's
    translation of numpy's shape errors).

    Examples
    --------
    >>> def half(x: float) -> float:
    ...     return x / 2
    >>> checked(half)(float("nan"))
    Traceback (most recent call last):
    ...
    ValueError: x must be finite (no NaN or infinity), got nan
    >>> unchecked(checked(half))(1.0), unchecked(half) is half
    (0.5, True)
    """
    if getattr(func, "__navcore_checked__", False):
        return func.__wrapped__  # type: ignore[attr-defined]
    return func


#: Errors numpy raises deep inside a computation when an input has the wrong shape; the
#: wrapper of :func:`checked` re-raises them as ``ValueError`` naming the arguments' shapes.
_SHAPE_ERRORS = (IndexError, np.exceptions.AxisError, np.linalg.LinAlgError, ValueError)
_NUMPY_SHAPE_WORDS = (
    "broadcast",
    "matmul",
    "reshape",
    "shape",
    "dimension",
    "truth value of an array",
    "cross product",
    "square",
    "Singular matrix",
    "inhomogeneous",
    "sequence",
)
_WRONG_TYPE_WORDS = (
    "not subscriptable",
    "not iterable",
    "has no len()",
    "unsupported operand",
    "not callable",
    "' object has no attribute '",
)


def _names_a_parameter(message: str, names: tuple[str, ...]) -> bool:
    return "arguments' shapes" in message or any(
        message.startswith(n) or f" {n} " in message or f"{n}=" in message for n in names
    )


def _is_numpy_shape_message(message: str) -> bool:
    return any(word in message for word in _NUMPY_SHAPE_WORDS)


def _is_wrong_type_message(message: str) -> bool:
    return any(word in message for word in _WRONG_TYPE_WORDS)


def _shapes(sig: inspect.Signature, args: tuple[Any, ...], kwargs: dict[str, Any]) -> str:
    """``name=shape`` (arrays) or ``name=type`` for the arguments of a failed call."""
    try:
        bound = sig.bind_partial(*args, **kwargs)
    except TypeError:
        return "arguments could not be bound"
    parts = []
    for name, value in bound.arguments.items():
        if isinstance(value, np.ndarray):
            parts.append(f"{name} shape {value.shape}")
        elif isinstance(value, list | tuple) and value and not isinstance(value[0], str):
            try:
                parts.append(f"{name} shape {np.shape(value)}")
            except ValueError:
                parts.append(f"{name} ragged {type(value).__name__}")
        elif isinstance(value, int | float | np.number) and not isinstance(value, bool):
            parts.append(f"{name} scalar")
        else:
            parts.append(f"{name} {type(value).__name__}")
    return ", ".join(parts)


#: Result records: dataclasses a model function returns (and fills with NaN where a value is
#: undefined, such as the prior at step 0); their constructors are not checked.
RESULT_RECORDS = frozenset(
    {
        "CovarianceAnalysis",
        "CovarianceHistory",
        "ConstellationParameters",
        "GainHistory",
        "GaussNewtonResult",
        "MechanizationTerms",
        "MonteCarloResult",
        "NavState",
        "NuisanceLMMSE",
        "RunResult",
        "SatelliteGeometry",
        "StratifiedSums",
        "TailBound",
        "Trajectory",
        "TrackerMonteCarlo",
    }
)


def check_public(
    namespace: dict[str, Any], ranges: dict[str, Range] | None = None, **options: dict[str, Any]
) -> None:
    """Wrap every public function of a module (its ``__all__``) with :func:`checked`.

    Called once at the end of a model module: ``check_public(globals())``. ``ranges`` maps
    parameter names to the :class:`Range` they mean throughout the module; other keyword
    arguments map a function name to its own ``checked`` options, e.g.
    ``check_public(globals(), {"p_d": OPEN_PROBABILITY}, f={"allow_inf": ("t",)})``.
    """
    for name in namespace.get("__all__", ()):
        obj = namespace[name]
        if inspect.isfunction(obj) and not getattr(obj, "__navcore_checked__", False):
            namespace[name] = checked(obj, **_merged(ranges, options.get(name, {})))
        elif (
            inspect.isclass(obj)
            and dataclasses.is_dataclass(obj)
            and obj.__module__ == namespace["__name__"]
            and name not in RESULT_RECORDS
        ):
            init = obj.__dict__.get("__init__")
            if init is not None and not getattr(init, "__navcore_checked__", False):
                setattr(obj, "__init__", checked(init, **_merged(ranges, options.get(name, {}))))  # noqa: B010


def _merged(ranges: dict[str, Range] | None, own: dict[str, Any]) -> dict[str, Any]:
    out = dict(own)
    out["ranges"] = {**(ranges or {}), **own.get("ranges", {})}
    return out
