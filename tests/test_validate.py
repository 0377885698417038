"""The validation layer (navcore._validate) at its edges, one table per check (issue 31, item 1).

Each check is given the values on both sides of its bound (the bound itself, the next float
beyond, NaN, an infinity, an empty array) and the exact message it must raise, which names the
parameter and the constraint. The public API's property test (test_api_inputs) reaches these
checks through the models; here each stands alone, so that a bound moved by one float or a
message that loses its parameter fails a test of its own.

Oracles: the documented constraint of each check written out by hand (an interval, a norm, a
determinant); numpy.linalg.eigvalsh for positive semi-definiteness.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence
from typing import Any, Literal

import numpy as np
import pytest

from navcore import _validate as v

NAN, INF = math.nan, math.inf


def _raises(exc: type[Exception], message: str, call: Callable[[], Any]) -> None:
    """``call`` raises ``exc`` with exactly ``message`` (a full match)."""
    with pytest.raises(exc) as info:
        call()
    assert str(info.value) == message


# --- as_finite_array, require_finite, power_ratio_from_db --------------------------------------------


def test_as_finite_array():
    out = v.as_finite_array("x", [1, 2])
    assert out.dtype == np.float64 and out.tolist() == [1.0, 2.0]
    assert v.as_finite_array("x", [[1.0]], ndim=2).shape == (1, 1)
    assert v.as_finite_array("x", np.zeros(0)).size == 0
    _raises(
        ValueError,
        "x must be a 2-dimensional array, got shape (2,)",
        lambda: v.as_finite_array("x", [1, 2], ndim=2),
    )
    _raises(
        ValueError,
        "x must be finite (no NaN or infinity), got [1.0, nan]",
        lambda: v.as_finite_array("x", [1.0, NAN]),
    )
    _raises(
        ValueError, "y must be finite (no NaN or infinity), got -inf", lambda: v.as_finite_array("y", -INF)
    )
    with pytest.raises(TypeError, match=r"^x must be a number or an array of numbers, got 'a' \("):
        v.as_finite_array("x", "a")
    with pytest.raises(
        TypeError, match=r"^x must be a number or an array of numbers, got \[1, \[2, 3\]\] \("
    ):
        v.as_finite_array("x", [1, [2, 3]])
    assert v.require_finite("x", 3).tolist() == 3.0
    _raises(ValueError, "z must be finite (no NaN or infinity), got nan", lambda: v.require_finite("z", NAN))


def test_power_ratio_from_db():
    assert v.power_ratio_from_db("g", [0.0, 10.0, -10.0]).tolist() == pytest.approx(
        [1.0, 10.0, 0.1], rel=1e-15
    )
    assert v.power_ratio_from_db("g", 3000.0) == pytest.approx(1e300, rel=1e-12)
    _raises(
        ValueError,
        "g must be at most 3000 dB (its power ratio overflows), got 3000.0000000000005",
        lambda: v.power_ratio_from_db("g", math.nextafter(3000.0, INF)),
    )
    _raises(
        ValueError, "g must be finite (no NaN or infinity), got nan", lambda: v.power_ratio_from_db("g", NAN)
    )


# --- require_* ---------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("check", "kwargs", "good", "bad", "message"),
    [
        (
            v.require_positive,
            {},
            [1e-300, 1.0, [1.0, 2.0]],
            [0.0, -1e-300, NAN, INF, [1.0, 0.0]],
            "must be > 0 and finite",
        ),
        (v.require_positive, {"allow_inf": True}, [1e-300, INF], [0.0, -INF, NAN], "must be > 0"),
        (
            v.require_nonnegative,
            {},
            [0.0, 1.0, [0.0, 1.0]],
            [-1e-300, NAN, INF, [0.0, -1.0]],
            "must be >= 0 and finite",
        ),
        (v.require_nonnegative, {"allow_inf": True}, [0.0, INF], [-1e-300, -INF, NAN], "must be >= 0"),
        (
            v.require_probability,
            {},
            [0.0, 0.5, 1.0, [0.0, 1.0]],
            [-1e-300, math.nextafter(1.0, 2.0), NAN],
            "must be a probability in [0, 1]",
        ),
        (
            v.require_probability,
            {"open_interval": True},
            [1e-300, 0.5, math.nextafter(1.0, 0.0)],
            [0.0, 1.0, NAN, -0.5, 1.5],
            "must be a probability in the open interval (0, 1)",
        ),
    ],
)
def test_require_bounds(check, kwargs, good, bad, message):
    for value in good:
        assert check("p", value, **kwargs) is value
    for value in bad:
        _raises(ValueError, f"p {message}, got {value!r}", lambda value=value: check("p", value, **kwargs))


def test_require_in_range():
    for value in (-1.0, 0.0, 2.0, [-1.0, 2.0]):
        assert v.require_in_range("a", value, -1.0, 2.0) is value
    for value in (math.nextafter(-1.0, -2.0), math.nextafter(2.0, 3.0), NAN, [0.0, 3.0]):
        _raises(
            ValueError,
            f"a must lie in [-1.0, 2.0], got {value!r}",
            lambda value=value: v.require_in_range("a", value, -1.0, 2.0),
        )


def test_require_integer():
    assert v.require_integer("n", 3) == 3
    out = v.require_integer("n", np.int64(4), minimum=4)
    assert out == 4 and type(out) is int
    assert v.require_integer("n", -5) == -5
    for bad in (True, 3.0, "3", None, np.float64(3)):
        _raises(ValueError, f"n must be an integer, got {bad!r}", lambda bad=bad: v.require_integer("n", bad))
    _raises(ValueError, "n must be an integer >= 2, got 1", lambda: v.require_integer("n", 1, minimum=2))
    assert v.require_integer("n", 0, minimum=0) == 0


def test_require_square():
    assert v.require_square("m", [[1, 2], [3, 4]]).tolist() == [[1.0, 2.0], [3.0, 4.0]]
    assert v.require_square("m", np.eye(3), size=3).shape == (3, 3)
    _raises(
        ValueError,
        "m must be a square matrix, got shape (2, 3)",
        lambda: v.require_square("m", np.ones((2, 3))),
    )
    _raises(ValueError, "m must be 3x3, got shape (2, 2)", lambda: v.require_square("m", np.eye(2), size=3))
    _raises(
        ValueError,
        "m must be a 2-dimensional array, got shape (3,)",
        lambda: v.require_square("m", np.ones(3)),
    )
    _raises(
        ValueError,
        "m must be finite (no NaN or infinity), got [[nan]]",
        lambda: v.require_square("m", [[NAN]]),
    )


def _psd_cases():
    rot = np.array([[0.6, -0.8], [0.8, 0.6]])
    return {
        "identity": (np.eye(3), True, True),
        "zero": (np.zeros((2, 2)), True, False),
        "rank one": (np.ones((2, 2)), True, False),
        "rank one, negative part below margin": (rot @ np.diag([1.0, -5e-10]) @ rot.T, True, False),
        "negative beyond margin": (rot @ np.diag([1.0, -2e-9]) @ rot.T, False, False),
        "negative diagonal": (np.diag([1.0, -1.0]), False, False),
        "all negative": (-np.eye(2), False, False),
        "tiny definite": (1e-300 * np.eye(2), True, True),
        "nearly singular definite": (np.diag([1.0, 1e-12]), True, True),
        "singular beyond the pivot margin": (np.array([[1.0, 1.0], [1.0, 1.0 + 1e-12]]), True, True),
        "definite, off-diagonal": (np.array([[2.0, 1.0], [1.0, 2.0]]), True, True),
    }


@pytest.mark.parametrize("case", sorted(_psd_cases()))
def test_symmetric_psd_against_eigenvalues(case):
    """Oracle: the eigenvalues (numpy.linalg.eigvalsh) against the margin rtol * largest."""
    arr, psd, definite = _psd_cases()[case]
    eig = np.linalg.eigvalsh(arr)
    assert psd == bool(eig[0] >= -1e-9 * max(eig[-1], 0.0))
    assert definite == bool(eig[0] > 0)
    for want, is_ok in ((False, psd), (True, definite)):
        if is_ok:
            assert v.require_symmetric_psd("P", arr, definite=want) is not None
            v.check_symmetric_psd("P", np.array(arr, dtype=float), definite=want)
        else:
            kind = "positive definite" if want else "positive semi-definite"
            with pytest.raises(ValueError, match=rf"^P must be {kind} \(smallest eigenvalue -?[0-9.e+-]+\)$"):
                v.require_symmetric_psd("P", arr, definite=want)


def test_symmetric_psd_messages_and_symmetry():
    _raises(
        ValueError,
        "P must be positive semi-definite (smallest eigenvalue -1)",
        lambda: v.require_symmetric_psd("P", np.diag([1.0, -1.0])),
    )
    _raises(
        ValueError,
        "P must be positive definite (smallest eigenvalue 0)",
        lambda: v.require_symmetric_psd("P", np.zeros((2, 2)), definite=True),
    )
    asym = np.array([[1.0, 0.0], [2e-8, 1.0]])
    _raises(ValueError, "P must be symmetric", lambda: v.require_symmetric_psd("P", asym))
    v.require_symmetric_psd("P", np.array([[1.0, 0.0], [5e-9, 1.0]]))  # within rtol * scale * 10
    v.require_symmetric_psd("P", np.array([[1.0, 0.0], [5e-9, 1.0]]) * 1e-200)  # the scale is relative
    _raises(
        ValueError,
        "P must be symmetric",
        lambda: v.require_symmetric_psd("P", np.array([[1.0, 0.0], [1e-6, 1.0]]), rtol=1e-8),
    )
    v.require_symmetric_psd("P", np.array([[1.0, 0.0], [1e-6, 1.0]]), rtol=1e-6)
    # the input is not modified by the check
    arr = np.array([[2.0, 1.0], [1.0, 2.0]])
    v.check_symmetric_psd("P", arr)
    assert arr.tolist() == [[2.0, 1.0], [1.0, 2.0]]


# --- ModelDomainError ----------------------------------------------------------------------------------


def test_model_domain_error():
    err = v.ModelDomainError("m")
    assert isinstance(err, ValueError) and str(err) == "m" and err.case == "m"
    assert v.ModelDomainError("m", case="c").case == "c"


# --- annotations -> checks ------------------------------------------------------------------------------


class Thing:
    pass


@pytest.mark.parametrize(
    ("annotation", "expected"),
    [
        ("float", ("number", False)),
        ("float | None", ("number", True)),
        ("float | int", ("number", False)),
        ("np.floating | float", ("number", False)),
        ("int", ("integer", False)),
        ("int | None", ("integer", True)),
        ("int | np.integer", (None, False)),
        ("ArrayLike", ("array", False)),
        ("NDArray[np.float64]", ("array", False)),
        ("ArrayLike | None", ("array", True)),
        ("np.ndarray", ("array", False)),
        ("Array", ("array", False)),
        ("FloatArray", ("array", False)),
        ("Sequence[float]", (None, False)),
        ("dict[str, float]", (None, False)),
        ("str", (None, False)),
        ("str | None", (None, True)),
        ("None", (None, True)),
        (float, ("number", False)),
        (int, ("integer", False)),
        (Thing, (None, False)),
    ],
)
def test_kind_of_an_annotation(annotation, expected):
    assert v._kind(annotation) == expected


NS = {"Thing": Thing, "np": np, "Sequence": Sequence, "Callable": Callable}


@pytest.mark.parametrize(
    ("annotation", "expected"),
    [
        ("Thing", (Thing,)),
        ("Thing | None", (Thing, type(None))),
        ("np.random.Generator | int | None", (np.random.Generator, np.integer, int, type(None))),
        ("bool", (bool, np.bool_)),
        ("float", (float, int, np.floating, np.integer)),
        ("str", (str,)),
        ("Sequence[Thing]", None),
        ("Any", None),
        ("Sequence", None),  # a typing/abc class
        ("Callable", None),
        ("Nothing", None),
        ("np.nothing", None),
        ("v.Constraint", None),  # a static protocol
        (Thing, None),  # not a string
    ],
)
def test_classes_of_an_annotation(annotation, expected):
    assert v._classes(annotation, {**NS, "v": v}) == expected


def test_classes_keeps_a_runtime_protocol():
    from typing import Protocol, runtime_checkable

    @runtime_checkable
    class Sized(Protocol):
        def size(self) -> int: ...

    assert v._classes("Sized", {"Sized": Sized}) == (Sized,)


@pytest.mark.parametrize(
    ("annotation", "expected"),
    [
        ("Callable[[float], float]", ["callable"]),
        ("Callable[..., Any] | None", None),
        ("Literal['a', 'b']", ["literal", ("a", "b")]),
        ("Literal[1]", ["literal", (1,)]),
        ("Literal[nope]", None),
        ("Literal[1, (]", None),
        ("Sequence[Thing]", ["sequence", (Thing,)]),
        ("list[Thing | None]", None),
        ("tuple[Thing, ...]", ["sequence", (Thing,)]),
        ("list[float]", None),
        ("list[int]", None),
        ("Sequence[Unknown]", None),
        ("dict[str, Thing]", None),
        ("Thing", None),
        (Thing, None),
    ],
)
def test_container_of_an_annotation(annotation, expected):
    assert v._container(annotation, NS) == expected


def test_check_container():
    v._check_container("f", len, ["callable"])
    _raises(TypeError, "f must be callable, got 3", lambda: v._check_container("f", 3, ["callable"]))
    v._check_container("m", "a", ["literal", ("a", "b")])
    _raises(
        ValueError,
        "m must be one of ['a', 'b'], got 'c'",
        lambda: v._check_container("m", "c", ["literal", ("a", "b")]),
    )
    _raises(
        ValueError,
        "m must be one of ['a'], got array(['a'], dtype='<U1')",
        lambda: v._check_container("m", np.array(["a"]), ["literal", ("a",)]),
    )
    v._check_container("s", [Thing(), Thing()], ["sequence", (Thing,)])
    v._check_container("s", (), ["sequence", (Thing,)])
    _raises(
        TypeError,
        "s must be a list or tuple, got Thing",
        lambda: v._check_container("s", Thing(), ["sequence", (Thing,)]),
    )
    _raises(
        TypeError,
        "s[1] must be of type Thing or str, got 3",
        lambda: v._check_container("s", [Thing(), 3], ["sequence", (Thing, str)]),
    )


@pytest.mark.parametrize(
    ("value", "kind", "allow_inf", "error"),
    [
        (3, "integer", False, None),
        (np.int32(3), "integer", False, None),
        (True, "integer", False, (TypeError, "n must be an integer, got True")),
        (3.0, "integer", False, (TypeError, "n must be an integer, got 3.0")),
        (1.5, "number", False, None),
        (2, "number", False, None),
        (np.float32(2), "number", False, None),
        (np.array(2.5), "number", False, None),
        (np.array(2), "number", False, None),
        (np.array(NAN), "number", False, (ValueError, "n must be finite (no NaN or infinity), got nan")),
        (np.array([2.5]), "number", False, (TypeError, "n must be a real number, got array([2.5])")),
        (np.array("a"), "number", False, (TypeError, "n must be a real number, got array('a', dtype='<U1')")),
        (np.array(True), "number", False, (TypeError, "n must be a real number, got array(True)")),
        (False, "number", False, (TypeError, "n must be a real number, got False")),
        ("1", "number", False, (TypeError, "n must be a real number, got '1'")),
        (NAN, "number", True, (ValueError, "n must be finite (no NaN or infinity), got nan")),
        (INF, "number", False, (ValueError, "n must be finite (no NaN or infinity), got inf")),
        (-INF, "number", False, (ValueError, "n must be finite (no NaN or infinity), got -inf")),
        (INF, "number", True, None),
        (-INF, "number", True, None),
        ([1.0, 2.0], "array", False, None),
        (np.array([1, 2]), "array", False, None),
        (np.array([True]), "array", False, None),
        (np.array([1 + 1j]), "array", False, None),
        (np.array([INF]), "array", True, None),
        (np.array([1.0, INF]), "array", False, (ValueError, "n must be finite (no NaN or infinity)")),
        ([1.0, NAN], "array", False, (ValueError, "n must be finite (no NaN or infinity)")),
        (np.array([NAN]), "array", True, (ValueError, "n must be finite (no NaN)")),
        (np.array([complex(INF, 0)]), "array", False, (ValueError, "n must be finite (no NaN or infinity)")),
        ("abc", "array", False, (TypeError, "n must be a number or an array of numbers, got 'abc'")),
        (b"abc", "array", False, (TypeError, "n must be a number or an array of numbers, got b'abc'")),
        (None, "array", False, (TypeError, "n must be a number or an array of numbers, got None")),
        (["a"], "array", False, (TypeError, "n must be a number or an array of numbers, got dtype <U1")),
        ({1: 2}, "array", False, (TypeError, "n must be a number or an array of numbers, got dtype object")),
    ],
)
def test_check_argument(value, kind, allow_inf, error):
    if error is None:
        v.check_argument("n", value, kind, allow_inf=allow_inf)
    else:
        _raises(*error, lambda: v.check_argument("n", value, kind, allow_inf=allow_inf))


def test_check_argument_ragged():
    with pytest.raises(ValueError, match=r"^n must be a rectangular array of numbers \(.*inhomogeneous"):
        v.check_argument("n", [[1.0], [1.0, 2.0]], "array")


# --- constraints ----------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("constraint", "text"),
    [
        (v.POSITIVE, "> 0"),
        (v.NONNEGATIVE, ">= 0"),
        (v.Range(None, 2.5), "<= 2.5"),
        (v.Range(None, 2.5, high_open=True), "< 2.5"),
        (v.PROBABILITY, "in [0, 1]"),
        (v.OPEN_PROBABILITY, "in (0, 1)"),
        (v.Range(0.0, 1.0, low_open=True), "in (0, 1]"),
        (v.Range(0.0, 1.0, high_open=True), "in [0, 1)"),
        (v.COUNT, "in [1, 1e+07]"),
        (v.COUNT0, "in [0, 1e+07]"),
    ],
)
def test_range_describe(constraint, text):
    assert constraint.describe() == text


@pytest.mark.parametrize(
    ("constraint", "good", "bad"),
    [
        (v.POSITIVE, [1e-300, 5, [1.0, 2.0], INF], [0.0, -1, NAN, -INF]),
        (v.NONNEGATIVE, [0.0, 0, np.uint8(3)], [-1e-300, -1, NAN]),
        (v.PROBABILITY, [0.0, 1.0, True], [math.nextafter(1.0, 2.0), -1e-300]),
        (v.OPEN_PROBABILITY, [1e-300, math.nextafter(1.0, 0.0)], [0.0, 1.0]),
        (v.Range(None, 2.0), [-INF, 2.0], [math.nextafter(2.0, 3.0)]),
        (v.Range(None, 2.0, high_open=True), [math.nextafter(2.0, 1.0)], [2.0]),
        (v.COUNT, [1, 10_000_000], [0, 10_000_001]),
        (v.COUNT0, [0], [-1]),
    ],
)
def test_range_check(constraint, good, bad):
    for value in good:
        constraint.check("x", value)
    for value in bad:
        _raises(
            ValueError,
            f"x must be {constraint.describe()}, got {value!r}",
            lambda value=value: constraint.check("x", value),
        )


def test_range_check_arrays_and_what_it_leaves():
    _raises(
        ValueError,
        "x must be > 0, got 'an array with 2 element(s) outside'",
        lambda: v.POSITIVE.check("x", [1.0, 0.0, -1.0, 2.0]),
    )
    _raises(ValueError, "x must be > 0, got [0.0]", lambda: v.POSITIVE.check("x", [0.0]))
    v.POSITIVE.check("x", np.array([]))  # empty
    v.POSITIVE.check("x", "text")  # not numeric: another check's business
    v.POSITIVE.check("x", np.array([1 + 0j]))
    v.Range().check("x", [-INF, INF])  # unbounded


@pytest.mark.parametrize(
    ("deg", "value", "message"),
    [
        (
            None,
            2.0,
            "lat must be a latitude in [-1.5708, 1.5708] rad (degrees? multiply by navcore.units.DEG), "
            "got 2.0",
        ),
        (False, -2.0, "lat must be a latitude in [-1.5708, 1.5708] rad (degrees? pass deg=True), got -2.0"),
        (True, 90.5, "lat must be a latitude in [-90, 90] deg, got 90.5"),
        (
            None,
            [0.0, 2.0, -3.0],
            "lat must be a latitude in [-1.5708, 1.5708] rad (degrees? multiply by navcore.units.DEG), "
            "got 'an array with |value| up to 3'",
        ),
    ],
)
def test_angle_rejects_beyond_its_limit(deg, value, message):
    _raises(ValueError, message, lambda: v.LATITUDE.check("lat", value, deg))


def test_angle_accepts_its_limit():
    limit = math.radians(90.0)
    for deg, good in ((None, [limit, -limit]), (False, limit), (True, [90.0, -90.0])):
        v.LATITUDE.check("lat", good, deg)
    v.LATITUDE.check("lat", math.nextafter(90.0, 0.0), True)
    v.LATITUDE.check("lat", np.array([]), None)
    v.LATITUDE.check("lat", "x", None)
    with pytest.raises(ValueError):
        v.LATITUDE.check("lat", math.nextafter(limit, 4.0), None)
    assert v.AZIMUTH.describe() == "an azimuth in [-6.28319, 6.28319] rad"
    assert v.LONGITUDE.describe(True) == "a longitude in [-360, 360] deg"
    assert v.ELEVATION.describe(deg=True) == "an elevation in [-90, 90] deg"


def test_unit_quaternion():
    q = np.array([0.5, 0.5, 0.5, 0.5])
    v.UNIT_QUATERNION.check("q", q)
    v.UNIT_QUATERNION.check("q", q * (1 + 0.9e-6))
    v.UNIT_QUATERNION_STACK.check("q", np.stack([q, [1.0, 0, 0, 0]]))
    v.UNIT_QUATERNION_STACK.check("q", np.zeros((0, 4)))
    _raises(
        ValueError,
        "q must be a unit quaternion (norm 1 to within 1e-06), got a norm of 1.00002; "
        "normalise it first (navcore.frames.quat_normalize)",
        lambda: v.UNIT_QUATERNION.check("q", q * 1.00002),
    )
    _raises(
        ValueError,
        "q must be a unit quaternion (norm 1 to within 1e-06), got a norm of 0.5; "
        "normalise it first (navcore.frames.quat_normalize)",
        lambda: v.UNIT_QUATERNION_STACK.check("q", [q, q * 0.5, q * 1.2]),
    )
    _raises(
        ValueError,
        "q must be a quaternion [w, x, y, z] of shape (4,), got shape (1, 4)",
        lambda: v.UNIT_QUATERNION.check("q", [q]),
    )
    _raises(
        ValueError,
        "q must be a quaternion [w, x, y, z] of shape (4,), got shape (3,)",
        lambda: v.UNIT_QUATERNION.check("q", q[:3]),
    )
    _raises(
        ValueError,
        "q must be a quaternion [w, x, y, z] or a stack of shape (..., 4), got shape (2, 3)",
        lambda: v.UNIT_QUATERNION_STACK.check("q", np.ones((2, 3))),
    )
    _raises(
        ValueError,
        "q must be a quaternion [w, x, y, z] or a stack of shape (..., 4), got shape ()",
        lambda: v.UNIT_QUATERNION_STACK.check("q", 1.0),
    )
    assert v.UNIT_QUATERNION.describe() == "a unit quaternion [w, x, y, z]"
    assert v.UNIT_QUATERNION_STACK.describe() == "a unit quaternion [w, x, y, z] or a stack (..., 4) of them"


def _rotation(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def test_rotation_matrix():
    r = _rotation(0.3)
    v.ROTATION.check("C", r)
    v.ROTATION_STACK.check("C", np.stack([r, _rotation(2.0)]))
    v.ROTATION_STACK.check("C", np.zeros((0, 3, 3)))
    v.ROTATION.check("C", r + 0.9e-6 * np.diag([1.0, 1.0, 0.0]) / 2)
    reflection = np.diag([1.0, 1.0, -1.0])
    for check, value in (
        (v.ROTATION, reflection),
        (v.ROTATION_STACK, np.stack([r, reflection])),
        (v.ROTATION, reflection @ r),
    ):
        _raises(
            ValueError,
            "C must be a proper rotation matrix (det +1), got a reflection (det -1)",
            lambda c=check, x=value: c.check("C", x),
        )
    _raises(
        ValueError,
        "C must be a rotation matrix (C C^T = I to within 1e-06), got C C^T - I up to 0.21",
        lambda: v.ROTATION.check("C", 1.1 * r),
    )
    _raises(
        ValueError,
        "C must be a rotation matrix of shape (3, 3), got shape (1, 3, 3)",
        lambda: v.ROTATION.check("C", [r]),
    )
    _raises(
        ValueError,
        "C must be a rotation matrix of shape (3, 3), got shape (3, 2)",
        lambda: v.ROTATION.check("C", r[:, :2]),
    )
    _raises(
        ValueError,
        "C must be a rotation matrix or a stack of shape (..., 3, 3), got shape (3,)",
        lambda: v.ROTATION_STACK.check("C", r[0]),
    )
    assert v.ROTATION.describe() == "a rotation matrix (3, 3)"
    assert v.ROTATION_STACK.describe() == "a rotation matrix (3, 3) or a stack (..., 3, 3) of them"


def test_covariance_shapes_and_descriptions():
    _raises(
        ValueError,
        "P must be a square covariance matrix of shape (n, n), got shape (2,)",
        lambda: v.COVARIANCE.check("P", [1.0, 2.0]),
    )
    _raises(
        ValueError,
        "P must be a square covariance matrix of shape (n, n), got shape (2, 3)",
        lambda: v.COVARIANCE.check("P", np.zeros((2, 3))),
    )
    _raises(
        ValueError,
        "P must be a square covariance matrix of shape (n, n), got shape (1, 2, 2)",
        lambda: v.COVARIANCE.check("P", np.zeros((1, 2, 2))),
    )
    _raises(
        ValueError,
        "P must be a square covariance matrix of shape (..., n, n), got shape (3, 2, 3)",
        lambda: v.COVARIANCE_STACK.check("P", np.zeros((3, 2, 3))),
    )
    v.COVARIANCE_STACK.check("P", np.zeros((0, 2, 2)))
    v.COVARIANCE.check("P", np.zeros((0, 0)))
    assert v.COVARIANCE.describe() == "a symmetric positive semi-definite matrix"
    assert (
        v.Covariance(stack=True, definite=True).describe()
        == "a symmetric positive definite matrix or a stack of them"
    )


def test_covariance_values():
    rot = np.array([[0.6, -0.8], [0.8, 0.6]])
    v.COVARIANCE.check("P", np.diag([1.0, 0.0]))
    v.COVARIANCE.check("P", rot @ np.diag([1.0, -5e-10]) @ rot.T)
    v.COVARIANCE_STACK.check("P", np.stack([np.eye(2), np.ones((2, 2))]))
    _raises(
        ValueError,
        "P must be positive semi-definite (a diagonal entry is -1)",
        lambda: v.COVARIANCE.check("P", np.diag([1.0, -1.0])),
    )
    _raises(
        ValueError,
        "P must be positive definite (a diagonal entry is 0)",
        lambda: v.Covariance(definite=True).check("P", np.diag([1.0, 0.0])),
    )
    v.Covariance(definite=True).check("P", np.diag([1.0, 1e-300]))
    _raises(
        ValueError,
        "P must be positive semi-definite (smallest eigenvalue -2e-09)",
        lambda: v.COVARIANCE.check("P", rot @ np.diag([1.0, -2e-9]) @ rot.T),
    )
    _raises(
        ValueError,
        "P must be positive definite (smallest eigenvalue 0)",
        lambda: v.Covariance(definite=True).check("P", np.ones((2, 2))),
    )
    _raises(
        ValueError,
        "P must be positive semi-definite (smallest eigenvalue -1)",
        lambda: v.COVARIANCE_STACK.check("P", np.stack([np.eye(2), np.array([[0.0, 1.0], [1.0, 0.0]])])),
    )
    _raises(
        ValueError,
        "P must be symmetric",
        lambda: v.COVARIANCE.check("P", np.array([[1.0, 0.0], [2e-8, 1.0]])),
    )
    v.COVARIANCE.check("P", np.array([[1.0, 0.0], [5e-9, 1.0]]))
    v.Covariance(rtol=1e-3).check("P", np.array([[1.0, 0.0], [5e-3, 1.0]]))


def test_covariance_with_infinite_variances():
    ok = v.Covariance(allow_inf_diagonal=True)
    ok.check("P", np.diag([INF, 1.0]))
    ok.check("P", np.array([[INF, 0.0, 0.0], [0.0, 2.0, 1.0], [0.0, 1.0, 2.0]]))
    _raises(ValueError, "P must not have a variance of -inf", lambda: ok.check("P", np.diag([-INF, 1.0])))
    _raises(
        ValueError,
        "P must be zero off the diagonal in a row or column of infinite variance",
        lambda: ok.check("P", np.array([[INF, 0.5], [0.5, 1.0]])),
    )
    _raises(
        ValueError,
        "P must be zero off the diagonal in a row or column of infinite variance",
        lambda: ok.check("P", np.array([[1.0, 0.0], [0.5, INF]])),
    )
    _raises(
        ValueError,
        "P must have infinite entries only on its diagonal",
        lambda: ok.check("P", np.array([[1.0, INF], [INF, 1.0]])),
    )
    _raises(
        ValueError,
        "P must be positive semi-definite (smallest eigenvalue -1)",
        lambda: ok.check("P", np.array([[INF, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]])),
    )


# --- checked, check_public, unchecked --------------------------------------------------------------


def _model(
    x: float,
    n: int,
    arr: ArrayLikeAlias,
    p: float | None = None,
    *,
    thing: Thing | None = None,
    mode: Literal["a", "b"] = "a",
    things: Sequence[Thing] = (),
    f: Callable[[float], float] | None = None,
    lat: float = 0.0,
    pair: tuple[float, float] = (0.0, 1.0),
    deg: bool = False,
    label: str = "",
    **rest: Any,
) -> float:
    return x


ArrayLikeAlias = "ArrayLike"  # the annotation is a string under `from __future__ import annotations`

RANGES = {"p": v.PROBABILITY, "lat": v.LATITUDE, "pair": v.NONNEGATIVE, "x": None, "absent": v.POSITIVE}


@pytest.mark.parametrize(
    ("args", "kwargs", "error"),
    [
        ((1.0, 2, [1.0]), {}, None),
        ((1.0, 2, [1.0], None), {"thing": None, "f": None}, None),
        ((1.0, 2, [1.0], 0.5), {"thing": Thing(), "mode": "b", "things": [Thing()], "f": abs}, None),
        ((NAN, 2, [1.0]), {}, (ValueError, "x must be finite (no NaN or infinity), got nan")),
        (
            (),
            {"x": NAN, "n": 2, "arr": [1.0]},
            (ValueError, "x must be finite (no NaN or infinity), got nan"),
        ),
        ((1.0, 2.0, [1.0]), {}, (TypeError, "n must be an integer, got 2.0")),
        ((1.0, 2, [INF]), {}, (ValueError, "arr must be finite (no NaN or infinity)")),
        ((1.0, 2, [1.0], 1.5), {}, (ValueError, "p must be in [0, 1], got 1.5")),
        ((1.0, 2, [1.0]), {"p": -0.5}, (ValueError, "p must be in [0, 1], got -0.5")),
        ((1.0, 2, [1.0]), {"thing": 3}, (TypeError, "thing must be of type Thing or NoneType, got 3")),
        ((1.0, 2, [1.0]), {"mode": "c"}, (ValueError, "mode must be one of ['a', 'b'], got 'c'")),
        ((1.0, 2, [1.0]), {"things": [3]}, (TypeError, "things[0] must be of type Thing, got 3")),
        ((1.0, 2, [1.0]), {"f": 3}, None),  # an optional callable is left to the function
        (
            (1.0, 2, [1.0]),
            {"lat": 2.0},
            (ValueError, "lat must be a latitude in [-1.5708, 1.5708] rad (degrees? pass deg=True), got 2.0"),
        ),
        ((1.0, 2, [1.0]), {"lat": 45.0, "deg": True}, None),
        (
            (1.0, 2, [1.0]),
            {"lat": 95.0, "deg": True},
            (ValueError, "lat must be a latitude in [-90, 90] deg, got 95.0"),
        ),
        ((1.0, 2, [1.0]), {"lat": 45.0, "deg": np.bool_(True)}, None),
        (
            (1.0, 2, [1.0]),
            {"lat": 45.0, "deg": 1},
            (
                ValueError,
                "lat must be a latitude in [-1.5708, 1.5708] rad (degrees? pass deg=True), got 45.0",
            ),
        ),
        (
            (1.0, 2, [1.0]),
            {"pair": (1.0, -1.0)},
            (ValueError, "pair must be >= 0, got 'an array with 1 element(s) outside'"),
        ),
        ((1.0, 2, [1.0]), {"pair": (1.0, NAN)}, (ValueError, "pair must be finite (no NaN or infinity)")),
        ((1.0, 2, [1.0]), {"label": "s", "extra": NAN}, None),  # **rest is not checked
        ((1.0, 2, [1.0]), {"label": 3}, (TypeError, "label must be of type str, got 3")),
        ((1.0, 2, [1.0]), {"validate": False, "x": 1.0}, (TypeError, None)),  # validate=False: no check
    ],
)
def test_checked_wrapper(args, kwargs, error):
    f = v.checked(_model, ranges=RANGES)
    if error is None:
        assert f(*args, **kwargs) == (args[0] if args else kwargs["x"])
    elif error[1] is None:
        with pytest.raises(error[0]):  # the unchecked call fails in Python's own argument binding
            f(*args, **kwargs)
    else:
        _raises(*error, lambda: f(*args, **kwargs))


def test_checked_validate_false_skips_the_checks():
    def g(x: float, validate: bool = True) -> float:
        return x

    out = v.checked(g)(NAN, validate=False)
    assert math.isnan(out)
    _raises(
        ValueError, "x must be finite (no NaN or infinity), got nan", lambda: v.checked(g)(NAN, validate=True)
    )


def test_checked_options():
    def g(x: float, y: float, z: ArrayLikeAlias, deg: bool = True, lat: float = 0.0) -> float:
        return 0.0

    f = v.checked(g, allow_inf=("x",), skip=("y",), ranges={"lat": v.LATITUDE})
    assert f(INF, NAN, [1.0]) == 0.0
    _raises(ValueError, "z must be finite (no NaN or infinity)", lambda: f(INF, NAN, [NAN]))
    # deg defaults to its declared default (True): degrees
    assert f(1.0, 1.0, [1.0], lat=80.0) == 0.0
    _raises(
        ValueError,
        "lat must be a latitude in [-1.5708, 1.5708] rad (degrees? pass deg=True), got 80.0",
        lambda: f(1.0, 1.0, [1.0], lat=80.0, deg=False),
    )
    assert (
        f.__navcore_checked__ is True and f.__wrapped__ is g and v.unchecked(f) is g and v.unchecked(g) is g
    )

    def h(lat: float, deg: bool = False) -> float:
        return lat

    _raises(
        ValueError,
        "lat must be a latitude in [-1.5708, 1.5708] rad (degrees? pass deg=True), got 80.0",
        lambda: v.checked(h, ranges={"lat": v.LATITUDE})(80.0),
    )

    def k(lat: float, deg=None) -> float:
        return lat

    _raises(
        ValueError,
        "lat must be a latitude in [-1.5708, 1.5708] rad (degrees? pass deg=True), got 80.0",
        lambda: v.checked(k, ranges={"lat": v.LATITUDE})(80.0),
    )

    def m(lat: float, deg) -> float:
        return lat

    _raises(
        ValueError,
        "lat must be a latitude in [-1.5708, 1.5708] rad (degrees? pass deg=True), got 80.0",
        lambda: v.checked(m, ranges={"lat": v.LATITUDE})(80.0, deg="yes"),
    )
    assert v.checked(m, ranges={"lat": v.LATITUDE})(80.0, deg=True) == 80.0


def test_checked_translates_numpy_errors():
    def shape(left: ArrayLikeAlias, right: ArrayLikeAlias) -> Any:
        return np.asarray(left) @ np.asarray(right)

    f = v.checked(shape)
    with pytest.raises(
        ValueError,
        match=r"^shape: the arguments' shapes do not fit the model "
        r"\(left shape \(2,\), right shape \(3,\)\); see its docstring for the shapes: matmul",
    ):
        f(np.ones(2), np.ones(3))

    def own(a: ArrayLikeAlias) -> Any:
        raise ValueError("a must have 3 elements, got a shape (2,)")

    _raises(ValueError, "a must have 3 elements, got a shape (2,)", lambda: v.checked(own)([1.0, 2.0]))

    def other(a: ArrayLikeAlias) -> Any:
        raise ValueError("something else went wrong")

    _raises(ValueError, "something else went wrong", lambda: v.checked(other)([1.0]))

    def index(a: ArrayLikeAlias) -> Any:
        return np.asarray(a)[5]

    with pytest.raises(
        ValueError, match=r"^index: the arguments' shapes do not fit the model \(a shape \(2,\)\)"
    ):
        v.checked(index)(np.ones(2))

    def typed(a: ArrayLikeAlias, t: Any = None) -> Any:
        return t[0]

    with pytest.raises(
        TypeError,
        match=r"^typed: an argument has the wrong type \(a shape \(1,\), t scalar\): "
        r"'int' object is not subscriptable$",
    ):
        v.checked(typed)([1.0], 3)

    def attribute(a: ArrayLikeAlias, t: Any = None) -> Any:
        return t.nope

    with pytest.raises(TypeError, match=r"^attribute: an argument has the wrong type"):
        v.checked(attribute)([1.0], 3)

    def named(a: ArrayLikeAlias, t: Any = None) -> Any:
        raise TypeError("t must be a widget, 'int' object is not subscriptable")

    _raises(
        TypeError, "t must be a widget, 'int' object is not subscriptable", lambda: v.checked(named)([1.0], 3)
    )

    def plain(a: ArrayLikeAlias) -> Any:
        raise TypeError("a plain error")

    _raises(TypeError, "a plain error", lambda: v.checked(plain)([1.0]))

    def attr_error(a: ArrayLikeAlias) -> Any:
        raise AttributeError("no such thing")

    with pytest.raises(AttributeError, match=r"^no such thing$"):
        v.checked(attr_error)([1.0])


@pytest.mark.parametrize(
    ("message", "expected"),
    [
        ("x must be positive", True),
        ("got x=3", True),
        ("the value of x is wrong", True),
        ("the arguments' shapes do not fit", True),
        ("zx must be", False),
        ("the max is wrong", False),
        ("fox", False),
    ],
)
def test_names_a_parameter(message, expected):
    assert v._names_a_parameter(message, ("x", "y")) is expected


def test_message_kinds():
    for word in v._NUMPY_SHAPE_WORDS:
        assert v._is_numpy_shape_message(f"a {word} b")
    assert not v._is_numpy_shape_message("nothing here")
    for word in v._WRONG_TYPE_WORDS:
        assert v._is_wrong_type_message(f"a {word} b")
    assert not v._is_wrong_type_message("nothing here")


def test_shapes_of_a_call():
    import inspect

    def g(a, b, c, d, e, f, h, i=None):
        return None

    sig = inspect.signature(g)
    text = v._shapes(
        sig, (np.ones((2, 3)), [1.0, 2.0], [[1], [1, 2]], 3, True, "s", ("a",)), {"i": np.float64(1.0)}
    )
    assert text == ("a shape (2, 3), b shape (2,), c ragged list, d scalar, e bool, f str, h tuple, i scalar")
    assert v._shapes(sig, (1, 2, 3, 4, 5, 6, 7, 8, 9), {}) == "arguments could not be bound"
    assert v._shapes(sig, ([],), {}) == "a list"


# --- check_public --------------------------------------------------------------------------------------


def test_check_public_wraps_public_functions_and_dataclass_constructors():
    import dataclasses

    def f(x: float) -> float:
        return x

    def g(x: float, t: float) -> float:
        return t

    def _private(x: float) -> float:
        return x

    @v.checks_own_arguments
    def own(x: float) -> float:
        return x

    @dataclasses.dataclass
    class Box:
        p: float

    Box.__module__ = "mod"

    @dataclasses.dataclass
    class Foreign:
        p: float

    Foreign.__module__ = "elsewhere"

    @dataclasses.dataclass
    class Trajectory:  # a result record: left unchecked
        p: float

    Trajectory.__module__ = "mod"

    class Plain:
        def __init__(self, p: float) -> None:
            self.p = p

    Plain.__module__ = "mod"
    ns = {
        "__name__": "mod",
        "__all__": ["f", "g", "own", "Box", "Foreign", "Trajectory", "Plain", "CONSTANT"],
        "f": f,
        "g": g,
        "_private": _private,
        "own": own,
        "Box": Box,
        "Foreign": Foreign,
        "Trajectory": Trajectory,
        "Plain": Plain,
        "CONSTANT": 3.0,
    }
    v.check_public(ns, {"p": v.PROBABILITY, "t": v.POSITIVE}, g={"allow_inf": ("t",), "ranges": {"t": None}})
    _raises(ValueError, "x must be finite (no NaN or infinity), got nan", lambda: ns["f"](NAN))
    assert ns["g"](1.0, INF) == INF  # its own options: infinity allowed, no range
    assert ns["g"](1.0, -1.0) == -1.0
    assert ns["own"] is own and ns["_private"] is _private and ns["CONSTANT"] == 3.0
    _raises(ValueError, "p must be in [0, 1], got 2.0", lambda: Box(2.0))
    assert Foreign(2.0).p == 2.0 and Trajectory(NAN) is not None and Plain(NAN) is not None
    init = Box.__init__
    v.check_public(ns, {"p": v.PROBABILITY})  # a second call wraps nothing twice
    assert Box.__init__ is init and ns["f"].__wrapped__ is f
    v.check_public({"__name__": "empty"})  # no __all__: nothing


def test_merged_options():
    assert v._merged(None, {}) == {"ranges": {}}
    assert v._merged({"a": 1, "b": 2}, {"ranges": {"b": 3}, "skip": ("c",)}) == {
        "ranges": {"a": 1, "b": 3},
        "skip": ("c",),
    }


def test_potrf_factor_and_failure():
    lower, info = v._potrf(np.array([[4.0, 2.0], [2.0, 3.0]]))
    assert info == 0
    np.testing.assert_allclose(np.tril(lower) @ np.tril(lower).T, [[4.0, 2.0], [2.0, 3.0]], rtol=1e-15)
    assert v._potrf(np.array([[1.0, 2.0], [2.0, 1.0]]))[1] > 0


def test_exported_names():
    assert set(v.__all__) <= set(dir(v))
    assert v.MAX_LOOP_COUNT == 10_000_000 and v.UNIT_TOLERANCE == 1e-6 and v.MAX_DECIBELS == 3000.0
    assert re.fullmatch(r"[a-z_ ]+", " ".join(v.RESULT_RECORDS).lower().replace("_", "")) is not None


# --- the edges a first mutation run found open (issue 31) -----------------------------------------------


def _with_eigen(values: Sequence[float], vectors: np.ndarray) -> np.ndarray:
    """Oracle: the symmetric matrix V diag(values) V^T with orthonormal columns V."""
    q, _ = np.linalg.qr(vectors)
    return q @ np.diag(values) @ q.T


# one direction per column: the first column is the eigenvector of the first value
_DIRS3 = np.array([[1.0, 1.0, 1.0], [1.0, -1.0, 1.0], [1.0, 0.0, -2.0]]).T


@pytest.mark.parametrize(
    ("values", "ok"),
    [
        # the fast Cholesky path fails (its shift, 1e-9 x the largest diagonal element, is below
        # 0.7e-9), the eigenvalue margin (1e-9 x the largest eigenvalue, 1) accepts
        ([1.0, 0.5, -0.7e-9], True),
        ([1.0, 0.5, -1.2e-9], False),
        # the margin follows the largest eigenvalue (0.5 here), not 1
        ([0.5, 0.25, -0.4e-9], True),
        ([0.5, 0.25, -0.8e-9], False),
        # a large matrix: the margin is relative (1e-9 x 100)
        ([100.0, 1.0, -5e-8], True),
        ([100.0, 1.0, -2e-7], False),
    ],
)
def test_psd_margin_is_relative_to_the_largest_eigenvalue(values, ok):
    """Oracle: the eigenvalues the matrix is built from, against -1e-9 x the largest."""
    arr = _with_eigen(values, _DIRS3)
    assert ok == (min(values) >= -1e-9 * max(values))
    for check in (
        lambda: v.require_symmetric_psd("P", arr),
        lambda: v.check_symmetric_psd("P", arr.copy()),
        lambda: v.COVARIANCE.check("P", arr),
        lambda: v.COVARIANCE_STACK.check("P", np.stack([np.eye(3), arr])),
    ):
        if ok:
            check()
        else:
            with pytest.raises(
                ValueError, match=r"^P must be positive semi-definite \(smallest eigenvalue -"
            ):
                check()


def test_psd_shift_is_on_the_diagonal_only_and_scales_with_the_matrix():
    """A negative eigenvalue along (1, 0, 1) that a shift of the corners too would hide, and a
    small matrix whose shift is relative to its size (1e-9 x 6e-4, not 1e-9 / 6e-4)."""
    corners = _with_eigen(
        [-1.5e-9, 1.0, 1.0], np.array([[1.0, 0.0, 1.0], [0.0, 1.0, 0.0], [1.0, 0.0, -1.0]]).T
    )
    small = _with_eigen([1e-3, -2e-12], np.array([[0.6, 0.8], [-0.8, 0.6]]).T)
    for arr in (corners, small):
        with pytest.raises(ValueError, match=r"^P must be positive semi-definite"):
            v.check_symmetric_psd("P", arr.copy())


def test_psd_defaults_and_definite_messages():
    v.check_symmetric_psd("P", np.ones((2, 2)))  # semi-definite by default
    with pytest.raises(ValueError, match=r"^P must be positive semi-definite"):
        v.check_symmetric_psd("P", _with_eigen([1.0, -2e-9], np.eye(2) + 0.3))  # rtol 1e-9 by default
    _raises(
        ValueError,
        "P must be positive definite (smallest eigenvalue 0)",
        lambda: v.require_symmetric_psd("P", np.diag([0.0, 1.0]), definite=True),
    )
    _raises(
        ValueError,
        "P must be a square matrix, got shape (2, 3)",
        lambda: v.require_symmetric_psd("P", np.ones((2, 3))),
    )


@pytest.mark.parametrize("scale", [1.0, 100.0, 1e-200])
def test_symmetry_bound_is_ten_rtol_times_the_scale(scale):
    """Oracle: |A - A^T| <= 10 rtol max|A| (rtol = 2^-20, so that the bound is exact in floats)."""
    rtol = 2.0**-20
    bound = 10 * rtol * scale
    at = np.array([[scale, 0.0], [bound, scale]])
    v.require_symmetric_psd("P", at, rtol=rtol)
    v.Covariance(rtol=rtol).check("P", at)
    beyond = np.array([[scale, 0.0], [bound * (1 + 2**-40), scale]])
    beyond_11 = np.array([[scale, 0.0], [bound * 1.05, scale]])
    for arr in (beyond, beyond_11):
        _raises(
            ValueError, "P must be symmetric", lambda arr=arr: v.require_symmetric_psd("P", arr, rtol=rtol)
        )
        _raises(ValueError, "P must be symmetric", lambda arr=arr: v.Covariance(rtol=rtol).check("P", arr))


def test_covariance_stacks_read_each_matrix():
    _raises(
        ValueError,
        "P must be positive semi-definite (a diagonal entry is -1)",
        lambda: v.COVARIANCE_STACK.check("P", np.stack([np.diag([1.0, 2.0]), np.diag([3.0, -1.0])])),
    )
    asym = np.array([[1.0, 0.5], [0.0, 1.0]])
    _raises(
        ValueError, "P must be symmetric", lambda: v.COVARIANCE_STACK.check("P", np.stack([np.eye(2), asym]))
    )
    v.Covariance(definite=True).check("P", np.array([[2.0, 1.0], [1.0, 2.0]]))  # smallest eigenvalue 1
    both = v.Covariance(stack=True, allow_inf_diagonal=True)
    _raises(
        ValueError,
        "P must be positive semi-definite (a diagonal entry is -1)",
        lambda: both.check("P", np.stack([np.diag([INF, 1.0]), np.diag([1.0, -1.0])])),
    )
    both.check("P", np.stack([np.diag([INF, 1.0]), np.diag([1.0, INF])]))


def test_infinite_variance_rows_become_zero():
    ok = v.Covariance(allow_inf_diagonal=True)
    ok.check("P", np.diag([INF, 0.25]))  # the infinite row and column are left out, not set to 1
    _raises(
        ValueError,
        "P must be positive semi-definite (a diagonal entry is -1)",
        lambda: ok.check("P", np.diag([INF, -1.0])),
    )


def test_potrf_loads_lapack_once(monkeypatch):
    monkeypatch.setattr(v, "_DPOTRF", None)
    lower, info = v._potrf(np.array([[4.0]]))
    assert info == 0 and lower[0, 0] == 2.0
    assert v._DPOTRF is not None
    cached = v._DPOTRF
    v._potrf(np.array([[1.0]]))
    assert v._DPOTRF is cached


def test_unit_quaternion_reports_the_worst_norm():
    q = np.array([1.0, 0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match=r"got a norm of 1\.2;"):
        v.UNIT_QUATERNION_STACK.check("q", [q, 1.2 * q])


def test_rotation_determinant_of_a_general_matrix():
    """Oracle: numpy.linalg.det of a rotation with every element non-zero, and of its negative."""
    a, b, c = 0.3, -0.7, 1.1
    rx = np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])
    ry = np.array([[math.cos(b), 0, math.sin(b)], [0, 1, 0], [-math.sin(b), 0, math.cos(b)]])
    rz = np.array([[math.cos(c), -math.sin(c), 0], [math.sin(c), math.cos(c), 0], [0, 0, 1]])
    r = rx @ ry @ rz
    assert np.all(np.abs(r) > 0.05) and np.linalg.det(r) == pytest.approx(1.0)
    v.ROTATION.check("C", r)
    v.ROTATION_STACK.check("C", np.stack([r, r.T]))
    for m in (-r, r[[1, 0, 2]]):
        assert np.linalg.det(m) == pytest.approx(-1.0)
        _raises(
            ValueError,
            "C must be a proper rotation matrix (det +1), got a reflection (det -1)",
            lambda m=m: v.ROTATION.check("C", m),
        )


@pytest.mark.parametrize(
    ("annotation", "expected"),
    [
        ("Sequence[float] | None", (None, False)),
        ("NDArray[np.dtype[np.float64]]", ("array", False)),
        ("float | int | np.floating | np.integer", ("number", False)),
        (3, (None, False)),  # no __name__
    ],
)
def test_kind_more(annotation, expected):
    assert v._kind(annotation) == expected


def test_classes_more():
    import typing

    ns = {"Thing": Thing, "Generic": typing.Generic}
    assert v._classes("None | Thing", ns) == (type(None), Thing)
    assert v._classes("Thing | bool", ns) == (Thing, bool, np.bool_)
    assert v._classes("Thing | float", ns) == (Thing, float, int, np.floating, np.integer)
    assert v._classes("Generic", ns) is None  # a class of the typing module


def test_container_list_head():
    assert v._container("list[Thing]", NS) == ["sequence", (Thing,)]


def test_checked_more():
    def f(
        x: float, window: tuple[float, float] | None = None, pair: tuple[float, float] = (0.0, 1.0)
    ) -> float:
        return x

    g = v.checked(f, ranges={"window": v.NONNEGATIVE, "pair": v.NONNEGATIVE})
    assert g(1.0, None) == 1.0 and g(1.0, window=(1.0, 2.0)) == 1.0
    _raises(
        ValueError,
        "window must be >= 0, got 'an array with 1 element(s) outside'",
        lambda: g(1.0, (1.0, -1.0)),
    )
    _raises(TypeError, "pair must be a number or an array of numbers, got None", lambda: g(1.0, pair=None))

    def star(x: float, *rest: float, k: float = 0.0) -> float:
        return x

    assert v.checked(star)(1.0, 2.0, NAN, k=1.0) == 1.0  # *rest is left to the function
    _raises(ValueError, "k must be finite (no NaN or infinity), got nan", lambda: v.checked(star)(1.0, k=NAN))

    @v.checked(ranges={"p": v.PROBABILITY})
    def decorated(p: float) -> float:
        return p

    assert decorated(0.5) == 0.5
    _raises(ValueError, "p must be in [0, 1], got 2.0", lambda: decorated(2.0))


def test_check_public_module_ranges_reach_functions_and_own_options_reach_constructors():
    import dataclasses

    def h(p: float) -> float:
        return p

    @dataclasses.dataclass
    class Box:
        t: float

    Box.__module__ = "mod"
    ns = {"__name__": "mod", "__all__": ["h", "Box"], "h": h, "Box": Box}
    v.check_public(ns, {"p": v.PROBABILITY}, Box={"ranges": {"t": v.POSITIVE}})
    _raises(ValueError, "p must be in [0, 1], got 2.0", lambda: ns["h"](2.0))
    _raises(ValueError, "t must be > 0, got -1.0", lambda: Box(-1.0))


def _rotation_with_first_row(row: Sequence[float]) -> np.ndarray:
    """A rotation whose first row is ``row`` (normalised), completed by Gram-Schmidt."""
    x = np.asarray(row, dtype=float) / np.linalg.norm(row)
    y = np.array([0.3, -0.5, 0.7]) - np.dot([0.3, -0.5, 0.7], x) * x
    y /= np.linalg.norm(y)
    return np.array([x, y, np.cross(x, y)])


@pytest.mark.parametrize("row", [(0.1, 0.15, 0.98), (0.12, 0.98, 0.1), (0.98, 0.1, 0.14), (0.6, -0.55, 0.58)])
def test_rotation_determinant_whichever_element_dominates(row):
    """Oracle: numpy.linalg.det. The cofactor expansion along the first row is a^2 + b^2 + c^2 for
    a rotation; a first row dominated by one element tells each of its three terms apart."""
    r = _rotation_with_first_row(row)
    assert np.linalg.det(r) == pytest.approx(1.0) and np.allclose(r @ r.T, np.eye(3))
    v.ROTATION.check("C", r)
    for m in (-r, r @ np.diag([1.0, 1.0, -1.0]), np.diag([-1.0, 1.0, 1.0]) @ r, r[[0, 2, 1]]):
        assert np.linalg.det(m) == pytest.approx(-1.0)
        _raises(
            ValueError,
            "C must be a proper rotation matrix (det +1), got a reflection (det -1)",
            lambda m=m: v.ROTATION.check("C", m),
        )


def test_rotation_by_quarter_turns_with_zero_elements():
    """Quarter turns about z and x: rotations with zero elements (and zero cofactors) pass."""
    for r in (
        [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
        [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]],
    ):
        assert np.linalg.det(r) == pytest.approx(1.0)
        v.ROTATION.check("C", r)
