"""Input validation shared by the models.

Every check raises ``ValueError`` whose message names the parameter and the constraint, so
that a bad input fails where it enters instead of travelling on as a NaN.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "as_finite_array",
    "require_finite",
    "require_in_range",
    "require_integer",
    "require_nonnegative",
    "require_positive",
    "require_probability",
    "require_square",
    "require_symmetric_psd",
]


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
