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
from typing import Any, Protocol, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "AZIMUTH",
    "COUNT",
    "COUNT0",
    "COVARIANCE",
    "COVARIANCE_STACK",
    "ELEVATION",
    "LATITUDE",
    "LONGITUDE",
    "MAX_LOOP_COUNT",
    "NONNEGATIVE",
    "OPEN_PROBABILITY",
    "POSITIVE",
    "PROBABILITY",
    "ROTATION",
    "ROTATION_STACK",
    "UNIT_QUATERNION",
    "UNIT_QUATERNION_STACK",
    "Angle",
    "Constraint",
    "Covariance",
    "ModelDomainError",
    "Range",
    "RotationMatrix",
    "UnitQuaternion",
    "as_finite_array",
    "check_argument",
    "check_public",
    "check_symmetric_psd",
    "checked",
    "checks_own_arguments",
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
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:  # a string, a ragged list, an object numpy cannot read
        raise TypeError(f"{name} must be a number or an array of numbers, got {value!r} ({exc})") from None
    if ndim is not None and arr.ndim != ndim:
        raise ValueError(f"{name} must be a {ndim}-dimensional array, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite (no NaN or infinity), got {value!r}")
    return arr


#: Largest decibel value whose power ratio 10**(x/10) is a finite float (float max ~ 1.8e308).
MAX_DECIBELS = 3000.0


def power_ratio_from_db(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """Return the power ratio ``10**(value/10)`` of a finite decibel array.

    A value above :data:`MAX_DECIBELS` (whose ratio overflows to infinity and would travel on
    as a zero noise term or an infinite ratio) is rejected by name.
    """
    arr = as_finite_array(name, value)
    if np.any(arr > MAX_DECIBELS):
        raise ValueError(
            f"{name} must be at most {MAX_DECIBELS:g} dB (its power ratio overflows), got {value!r}"
        )
    return np.power(10.0, arr / 10.0)


def require_finite(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """Check that ``value`` is finite everywhere and return it as an array."""
    return as_finite_array(name, value)


class ModelDomainError(ValueError):
    """Valid inputs that together describe a case the model does not cover.

    Each input is in its own range, but their combination asks the model for something its
    construction excludes: for example a flight along which fewer satellites stay above the
    elevation mask than the receiver model tracks on fixed channels. A ``ValueError``, so a
    caller who catches bad input catches it too; the ledger tells it apart when it runs a claim
    across its assumed inputs' ranges (a corner of that box the model does not cover is left
    out of the band and said, not taken as a failure of the claim).

    Parameters
    ----------
    message : str
        What is out of the model's domain, for the caller: parameters as the caller spelled
        them (``mask_deg=15.0``).
    case : str, optional
        The same case in a reader's words, without parameter names (the ledger shows it when a
        band leaves the run out); defaults to ``message``.

    Examples
    --------
    >>> issubclass(ModelDomainError, ValueError)
    True
    >>> err = ModelDomainError("3 satellites above mask_deg=15.0",
    ...                        case="3 satellites above the mask")
    >>> str(err)
    '3 satellites above mask_deg=15.0'
    >>> err.case
    '3 satellites above the mask'
    """

    def __init__(self, message: str, *, case: str | None = None) -> None:
        super().__init__(message)
        self.case = message if case is None else case


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


class Constraint(Protocol):
    """What :func:`checked` asks of a constraint: ``check(name, value, deg)`` raises
    ``ValueError`` naming ``name`` (``deg`` is the call's ``deg`` keyword, ``None`` if the
    function has none)."""

    def check(self, name: str, value: Any, deg: bool | None = None) -> None: ...


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

    def check(self, name: str, value: Any, deg: bool | None = None) -> None:
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


#: How far from 1 the norm of a unit quaternion, and from the identity ``C C^T`` of a
#: rotation matrix, may be (round-off of a normalised value is about 1e-15; a value typed to
#: seven digits is within 1e-6).
UNIT_TOLERANCE = 1e-6
_EYE3 = np.eye(3)


@dataclasses.dataclass(frozen=True)
class Angle:
    """An angle bounded in magnitude: ``|value| <= limit_deg`` degrees.

    The value is in radians, or in degrees when the call passes ``deg=True`` (``deg`` is
    given to :meth:`check` by :func:`checked`; ``None`` means the function has no ``deg``
    keyword). A latitude of 45 given where radians are expected fails here, with a hint.
    """

    limit_deg: float
    what: str

    def describe(self, deg: bool = False) -> str:
        limit = self.limit_deg if deg else math.radians(self.limit_deg)
        return f"{self.what} in [{-limit:.6g}, {limit:.6g}] {'deg' if deg else 'rad'}"

    def check(self, name: str, value: Any, deg: bool | None = None) -> None:
        arr = np.asarray(value)
        if arr.dtype.kind not in "biuf" or arr.size == 0:
            return
        in_deg = bool(deg)
        limit = self.limit_deg if in_deg else math.radians(self.limit_deg)
        worst = float(np.max(np.abs(arr)))
        if worst > limit:
            if in_deg:
                hint = ""
            elif deg is None:
                hint = " (degrees? multiply by navcore.units.DEG)"
            else:
                hint = " (degrees? pass deg=True)"
            shown = value if arr.size == 1 else f"an array with |value| up to {worst:g}"
            raise ValueError(f"{name} must be {self.describe(in_deg)}{hint}, got {shown!r}")


LATITUDE = Angle(90.0, "a latitude")
LONGITUDE = Angle(360.0, "a longitude")
ELEVATION = Angle(90.0, "an elevation")
AZIMUTH = Angle(360.0, "an azimuth")


def _stack_shape(name: str, arr: NDArray[Any], tail: tuple[int, ...], stack: bool, what: str) -> None:
    k = len(tail)
    if arr.ndim < k or arr.shape[arr.ndim - k :] != tail or (not stack and arr.ndim != k):
        want = f"(..., {', '.join(map(str, tail))})" if stack else str(tail)
        raise ValueError(f"{name} must be {what} of shape {want}, got shape {arr.shape}")


@dataclasses.dataclass(frozen=True)
class UnitQuaternion:
    """A unit quaternion ``[w, x, y, z]`` (or a stack ``(..., 4)`` with ``stack``).

    Its norm must be 1 to within :data:`UNIT_TOLERANCE`: a rotation by a non-unit
    quaternion scales the vector by the squared norm.
    """

    stack: bool = True

    def describe(self) -> str:
        return "a unit quaternion [w, x, y, z]" + (" or a stack (..., 4) of them" if self.stack else "")

    def check(self, name: str, value: Any, deg: bool | None = None) -> None:
        arr = np.asarray(value, dtype=float)
        _stack_shape(
            name, arr, (4,), self.stack, "a quaternion [w, x, y, z]" + (" or a stack" if self.stack else "")
        )
        if arr.size == 0:
            return
        norm = np.sqrt(np.einsum("...i,...i->...", arr, arr)).ravel()
        i = int(np.argmax(np.abs(norm - 1.0)))
        if abs(norm[i] - 1.0) > UNIT_TOLERANCE:
            raise ValueError(
                f"{name} must be a unit quaternion (norm 1 to within {UNIT_TOLERANCE:g}), got a norm of "
                f"{norm[i]:.6g}; normalise it first (navcore.frames.quat_normalize)"
            )


@dataclasses.dataclass(frozen=True)
class RotationMatrix:
    """A proper rotation matrix (3, 3) (or a stack ``(..., 3, 3)`` with ``stack``).

    ``C C^T = I`` to within :data:`UNIT_TOLERANCE` and ``det C = +1``.
    """

    stack: bool = True

    def describe(self) -> str:
        return "a rotation matrix (3, 3)" + (" or a stack (..., 3, 3) of them" if self.stack else "")

    def check(self, name: str, value: Any, deg: bool | None = None) -> None:
        arr = np.asarray(value, dtype=float)
        _stack_shape(
            name, arr, (3, 3), self.stack, "a rotation matrix" + (" or a stack" if self.stack else "")
        )
        if arr.size == 0:
            return
        worst = float(np.abs(np.matmul(arr, np.swapaxes(arr, -1, -2)) - _EYE3).max())
        if worst > UNIT_TOLERANCE:
            raise ValueError(
                f"{name} must be a rotation matrix (C C^T = I to within {UNIT_TOLERANCE:g}), "
                f"got C C^T - I up to {worst:.3g}"
            )
        if arr.ndim == 2:  # one matrix: the triple product in plain floats is the cheapest
            (a, b, c), (d, e, f), (g, h, i) = arr.tolist()
            det: Any = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
        else:
            det = np.linalg.det(arr)
        if np.any(det < 0.0):
            raise ValueError(f"{name} must be a proper rotation matrix (det +1), got a reflection (det -1)")


@dataclasses.dataclass(frozen=True)
class Covariance:
    """A covariance: a symmetric positive semi-definite square matrix.

    ``stack`` accepts ``(..., n, n)``; ``definite`` requires positive definite;
    ``allow_inf_diagonal`` accepts ``+inf`` on the diagonal (an infinite variance, i.e. no
    information) with zeros off the diagonal of that row and column. Symmetry is tested
    relative to the matrix scale and the eigenvalues allow a round-off margin of ``rtol``
    times the largest one. A diagonal matrix is checked by its diagonal alone.
    """

    stack: bool = False
    definite: bool = False
    allow_inf_diagonal: bool = False
    rtol: float = 1e-9

    def describe(self) -> str:
        kind = "positive definite" if self.definite else "positive semi-definite"
        return f"a symmetric {kind} matrix" + (" or a stack of them" if self.stack else "")

    def check(self, name: str, value: Any, deg: bool | None = None) -> None:
        arr = np.asarray(value, dtype=float)
        if arr.ndim < 2 or arr.shape[-1] != arr.shape[-2] or (not self.stack and arr.ndim != 2):
            want = "(..., n, n)" if self.stack else "(n, n)"
            raise ValueError(
                f"{name} must be a square covariance matrix of shape {want}, got shape {arr.shape}"
            )
        if arr.size == 0:
            return
        diag = np.diagonal(arr, axis1=-2, axis2=-1)
        if self.allow_inf_diagonal and not np.isfinite(arr).all():  # (NaN was rejected before)
            inf = np.isinf(diag)
            if np.any(diag[inf] < 0):
                raise ValueError(f"{name} must not have a variance of -inf")
            lines = inf[..., :, None] | inf[..., None, :]
            off = lines & ~np.eye(arr.shape[-1], dtype=bool)
            if np.any(arr[off] != 0.0):
                raise ValueError(
                    f"{name} must be zero off the diagonal in a row or column of infinite variance"
                )
            arr = np.where(lines, 0.0, arr)
            if not np.isfinite(arr).all():
                raise ValueError(f"{name} must have infinite entries only on its diagonal")
            diag = np.diagonal(arr, axis1=-2, axis2=-1)
        _require_psd(name, arr, diag, self.rtol, self.definite)


def _require_psd(
    name: str, arr: NDArray[np.float64], diag: NDArray[np.float64], rtol: float, definite: bool
) -> None:
    kind = "positive definite" if definite else "positive semi-definite"
    if np.count_nonzero(arr) == np.count_nonzero(diag):  # diagonal: the variances decide
        low = diag.min()
        if low < 0 or (definite and low <= 0):
            raise ValueError(f"{name} must be {kind} (a diagonal entry is {low:.3g})")
        return
    scale = max(float(np.abs(arr).max()), np.finfo(float).tiny)
    arr_t = np.swapaxes(arr, -1, -2)
    if np.abs(arr - arr_t).max() > rtol * scale * 10:
        raise ValueError(f"{name} must be symmetric")
    eig = np.linalg.eigvalsh(0.5 * (arr + arr_t))
    smallest = eig[..., 0]
    if definite and np.any(smallest <= 0):
        raise ValueError(f"{name} must be {kind} (smallest eigenvalue {float(np.min(smallest)):.3g})")
    if np.any(smallest < -rtol * np.maximum(eig[..., -1], 0.0)):
        raise ValueError(f"{name} must be {kind} (smallest eigenvalue {float(np.min(smallest)):.3g})")


UNIT_QUATERNION = UnitQuaternion(stack=False)
UNIT_QUATERNION_STACK = UnitQuaternion(stack=True)
ROTATION = RotationMatrix(stack=False)
ROTATION_STACK = RotationMatrix(stack=True)
COVARIANCE = Covariance()
COVARIANCE_STACK = Covariance(stack=True)


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
    if type(value) is np.ndarray and value.dtype.kind == "f":  # the common case: no conversion
        arr = value
    else:  # array: anything numpy turns into a numeric array
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
    ranges: dict[str, Constraint | None] | None = None,
) -> Any:
    """Decorator: check every numeric argument of ``func`` against its annotation.

    A parameter annotated ``float`` must be a real number and finite; ``int`` an integer
    (not ``bool``); ``ArrayLike``/``NDArray`` anything numpy turns into a numeric,
    rectangular array, finite everywhere. ``None`` passes where the annotation allows it.
    ``allow_inf`` lists parameters for which infinity is a meaningful value; ``skip`` lists
    parameters left to the function's own checks; ``ranges`` maps a parameter name to the
    :class:`Range` its value must lie in (a name the function does not have is ignored, so a
    module can state its conventions once: ``p_d`` is a probability, ``k`` a count), or to a
    constraint of another kind: an :class:`Angle` (bounded by its unit: radians, or degrees
    when the call passes ``deg=True``), a :class:`UnitQuaternion`, a :class:`RotationMatrix`
    or a :class:`Covariance` (these check their shapes too); ``None`` removes a module-wide
    entry for one function. Other shape constraints stay in the function body. Every
    failure raises a ``TypeError`` or ``ValueError`` that names the parameter as the caller
    spelled it.

    A call with ``validate=False`` (for functions that have that keyword) skips the checks.
    """

    def wrap(f: Callable[..., _R]) -> Callable[..., _R]:
        sig = inspect.signature(f)
        specs: list[tuple[int | None, str, Any, bool, bool, Constraint | None]] = []
        for i, p in enumerate(sig.parameters.values()):
            if p.name in skip or p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
                continue
            constraint = (ranges or {}).get(p.name)
            kind: Any
            kind, allows_none = _kind(p.annotation)
            if kind is None:
                kind = _classes(p.annotation, f.__globals__)  # a tuple of classes, or None
            if kind is None:
                kind = _container(p.annotation, f.__globals__)  # ("literal"|"sequence", ...)
                if kind is None and constraint is not None:
                    kind = _ARRAY  # e.g. a tuple of floats with a range
                    allows_none = "None" in str(p.annotation)
                if kind is None:
                    continue
            pos = i if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD) else None
            specs.append((pos, p.name, kind, allows_none, p.name in allow_inf, constraint))
        names = tuple(sig.parameters)
        deg_param = sig.parameters.get("deg")
        has_deg = deg_param is not None
        deg_default = (
            bool(deg_param.default)
            if deg_param is not None and deg_param.default is not inspect.Parameter.empty
            else False
        )

        @functools.wraps(f)
        def wrapper(*args: Any, **kwargs: Any) -> _R:
            if kwargs.get("validate", True) is False:  # the caller checked at its boundary
                return f(*args, **kwargs)
            n = len(args)
            deg: bool | None = None
            if has_deg:  # a deg that is not a bool fails its own type check below
                deg_value = kwargs.get("deg", deg_default)
                deg = bool(deg_value) if isinstance(deg_value, bool | np.bool_) else False
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
                    interval.check(name, value, deg)
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


def checks_own_arguments(func: Callable[..., _R]) -> Callable[..., _R]:
    """Mark ``func`` as checking every argument in its own body: :func:`check_public` leaves it.

    For the few kernels a filter calls at every step (:func:`navcore.estimation.kalman.kf_predict`
    and ``kf_update``), where the generic wrapper's work would be a large part of the step's
    cost. The body must raise as the wrapper does: a ``TypeError`` or ``ValueError`` that names
    the parameter as the caller spelled it.

    Examples
    --------
    >>> @checks_own_arguments
    ... def half(x: float) -> float:
    ...     if not isinstance(x, float) or x != x:
    ...         raise ValueError(f"x must be a finite float, got {x!r}")
    ...     return x / 2
    >>> check_public({"__all__": ["half"], "half": half, "__name__": "doc"})  # leaves it as is
    >>> half(1.0), half.__navcore_checked__
    (0.5, True)
    """
    func.__navcore_checked__ = True  # type: ignore[attr-defined]
    return func


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
        "DilutionOfPrecision",
        "FalseTrackRates",
        "ConstellationParameters",
        "GainHistory",
        "GaussNewtonResult",
        "ListRates",
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
        "WindowRates",
    }
)


def check_public(
    namespace: dict[str, Any], ranges: dict[str, Any] | None = None, **options: dict[str, Any]
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


def _merged(ranges: dict[str, Any] | None, own: dict[str, Any]) -> dict[str, Any]:
    out = dict(own)
    out["ranges"] = {**(ranges or {}), **own.get("ranges", {})}
    return out
