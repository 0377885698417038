"""The input gate's working parts, called in the test process (issue 31, mutation testing).

``tests/test_input_gate.py`` runs the whole gate on a planted package, but the gate evaluates
claims in forked children, which mutation testing cannot see. Here ``tools/input_gate.py`` is
loaded under its dotted name ``tools.input_gate`` (the name mutmut's trampolines recognise) and
its functions are called directly:

* the syntax helpers (``_literal_value``, ``_ref``, ``_is_structure``, ``_simple_exponent``,
  ``_mentions_log10``), every rule of ``classify_rule`` with its edges, ``_identity_default``;
* the indexer (``index_package``) on a tiny package written to ``tmp_path``: candidates, their
  scopes, bindings, rules and units, the import bindings, excluded modules, the allowlist;
* name resolution (``Resolver``) and ``relevance`` from hand-written traces;
* the children's work run in this process on a tiny claims package: ``claims_metadata``,
  ``trace_claim``, ``evaluate_perturbed`` (a literal rewritten at import), ``_Exposure``;
* ``compare`` and ``Effect``, the perturbation values, the gate's verdicts (``_flags``,
  ``_moves``, ``_status``), its report, ``merge_reports``, ``reapply_rules``,
  ``render_markdown``, ``suggest_class``, the trace cache and the scheduler.

Oracle in each test: the hand-made input and the result worked out by hand (named in each
docstring).
"""

from __future__ import annotations

import ast
import json
import math
import re
import sys
import textwrap
import time
from pathlib import Path
from typing import Any, ClassVar

import pytest

from tests._tools import load_tool

gate = load_tool("input_gate")


# --- small helpers ----------------------------------------------------------------------------


def _expr(src: str) -> ast.AST:
    return ast.parse(src, mode="eval").body


def _rule(source: str, literal: str, where: str = "body", binding: str = "", nth: int = 0) -> str:
    """The rule the gate applies to the ``nth`` literal written ``literal`` in ``source``."""
    source = textwrap.dedent(source)
    tree = ast.parse(source)
    parents = {c: p for p in ast.walk(tree) for c in ast.iter_child_nodes(p)}
    lines = source.splitlines()
    found = []
    for node in ast.walk(tree):
        if gate._literal_value(node) is not None and hasattr(node, "lineno"):
            if isinstance(parents.get(node), ast.UnaryOp) and gate._literal_value(parents[node]) is not None:
                continue  # the constant inside -x: the literal is -x
            text = lines[node.lineno - 1].encode()[node.col_offset : node.end_col_offset].decode()
            if text == literal:
                found.append(node)
    found.sort(key=lambda n: (n.lineno, n.col_offset))
    assert len(found) > nth, f"{literal} not in source"
    return gate.classify_rule(found[nth], parents, where, binding)


def _write_pkg(root: Path, files: dict[str, str]) -> None:
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text).lstrip("\n"))


# --- syntax helpers ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("src", "value"),
    [
        ("3", 3),
        ("2.5", 2.5),
        ("-2.5", -2.5),
        ("+4", 4),
        ("-0", 0),
        ("True", None),  # a bool is not a number here
        ("'3'", None),
        ("1j", None),
        ("-x", None),
        ("not 3", None),
        ("~3", None),
        ("-(-3)", None),  # only a sign directly on a literal
        ("-True", None),
        ("x", None),
    ],
)
def test_literal_value(src: str, value: Any) -> None:
    """Oracle: the number each snippet writes, by reading it (None where it writes none)."""
    got = gate._literal_value(_expr(src))
    assert got == value and type(got) is type(value)


@pytest.mark.parametrize(
    ("src", "ref"),
    [
        ("x", ("x",)),
        ("a.b", ("a", "b")),
        ("np.linalg.norm", ("np", "linalg", "norm")),
        ("f().b", None),
        ("a[0].b", None),
        ("3", None),
    ],
)
def test_ref(src: str, ref: Any) -> None:
    """Oracle: the dotted name each snippet spells, part by part."""
    assert gate._ref(_expr(src)) == ref


@pytest.mark.parametrize(
    ("src", "structure"),
    [
        ("len(x) - 1", True),
        ("np.ndim(x)", True),
        ("np.size(x)", True),
        ("np.shape(x)", True),
        ("np.linalg.matrix_rank(a)", True),
        ("x.shape[0]", True),
        ("x.size * 2", True),
        ("a.ndim", True),
        ("a.length + 1", False),
        ("f(x) + 1", False),
        ("(lambda: 0)()", False),
        ("np.sum(x)", False),
    ],
)
def test_is_structure(src: str, structure: bool) -> None:
    """Oracle: len/ndim/size/shape/matrix_rank calls and .shape/.size/.ndim are array structure."""
    assert gate._is_structure(_expr(src)) is structure


@pytest.mark.parametrize(
    ("v", "simple"),
    [
        (2.0, True),
        (0.5, True),
        (1 / 3, True),
        (2 / 3, True),
        (0.25, True),
        (0.75, True),
        (4.0, True),
        (-4.0, True),
        (-0.5, True),
        (4.5, False),  # beyond 4
        (-4.25, False),
        (0.8, False),  # a fitted power law
        (0.2, False),
        (0.3333, False),
        (1 / 3 + 1e-9, False),
    ],
)
def test_simple_exponent(v: float, simple: bool) -> None:
    """Oracle: integer, half, third and quarter exponents up to 4 in size are the formula's form."""
    assert gate._simple_exponent(v) is simple


@pytest.mark.parametrize(
    ("src", "mentions"),
    [
        ("np.log10(p)", True),
        ("to_db(p)", True),
        ("x + ratio_dB(p)", True),
        ("10 ** x", True),
        ("10.0 ** (x / 10)", True),
        ("2 ** x", False),
        ("x ** 10", False),
        ("np.power(10, x)", True),
        ("np.power(10.0, x)", True),
        ("np.power(2, x)", False),
        ("np.power(x, 10)", False),
        ("power()", False),
        ("np.log(p)", False),
        ("f(x)", False),
        ("(lambda: 1)()", False),
    ],
)
def test_mentions_log10(src: str, mentions: bool) -> None:
    """Oracle: a log10 or a *db* call, 10 ** x or np.power(10, x) are decibel conversions."""
    assert gate._mentions_log10(_expr(src)) is mentions


# --- classify_rule ----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("source", "literal", "where", "rule"),
    [
        # text
        ("s = f'{x:.3f} {2.5}'", "2.5", "body", "text"),
        ("warnings.warn('too big', 3.5)", "3.5", "body", "text"),
        ("print(4.5)", "4.5", "body", "text"),
        ("log.debug('%s', 4.5)", "4.5", "body", "text"),
        ("s = fmt.format(4.5)", "4.5", "body", "text"),
        ("s = '{}'.format(4.5)", "4.5", "body", ""),  # not a dotted name: not recognised
        ("logger.error('x', 7.5)", "7.5", "body", "text"),
        # checks
        ("assert x < 3.5", "3.5", "body", "raise"),
        ("raise ValueError(2.5)", "2.5", "body", "raise"),
        ("require_positive(x, 5.5)", "5.5", "body", "raise"),
        ("y = check_range(x, 2.5)", "2.5", "body", "raise"),
        ("y = _require_finite(x, 2.5)", "2.5", "body", "raise"),
        ("y = _check_shape(x, 2.5)", "2.5", "body", "raise"),
        ("y = requires(x, 2.5)", "2.5", "body", ""),
        # annotations
        ("def f(x: Annotated[float, 3.5]): pass", "3.5", "body", "annotation"),
        ("y: Annotated[float, 3.5] = 2.5", "3.5", "module", "annotation"),
        ("y: Annotated[float, 3.5] = 2.5", "2.5", "module", ""),
        ("def f() -> Annotated[float, 3.5]: pass", "3.5", "body", "annotation"),
        # declarations and claim metadata
        ("IN.assumed('x', 3.5, low=1.5, high=5.5)", "5.5", "module", "declared-input"),
        ("IN.fitted('x', 3.5)", "3.5", "module", "declared-input"),
        ("IN.convention('x', 3.5)", "3.5", "module", "declared-input"),
        ("published('x', 3.5)", "3.5", "module", ""),  # not a method of an InputSet
        ("c = Claim(id='x', published=35.5)", "35.5", "module", "claim-metadata"),
        ("t = Tolerance(abs=0.5)", "0.5", "module", "claim-metadata"),
        ("t = nc.monte_carlo(2.5)", "2.5", "module", "claim-metadata"),
        ("c = Claim(compute=lambda: 2.7 * x)", "2.7", "module", ""),  # the compute is code
        ("c = Claim(compute=lambda: f(2.7))", "2.7", "module", ""),
        # a function body is the boundary: a def inside a Claim(...) call is not possible, but a
        # lambda default is code too
        # seeds
        ("rng = np.random.default_rng(12345)", "12345", "body", "seed"),
        ("rng = RandomState(7)", "7", "module", "seed"),
        ("y = f(x, seed=7)", "7", "body", "seed"),
        ("y = f(x, rng_Seed=7)", "7", "body", "seed"),
        # index and structure
        ("d = {3.5: 'a'}", "3.5", "module", "index"),
        ("d = {'a': 3.5}", "3.5", "module", ""),
        ("y = x[3]", "3", "body", "index"),
        ("y = x[2:5]", "5", "body", "index"),
        ("y = x[-2]", "-2", "body", "index"),
        ("y = x[(2, 3)]", "3", "body", "index"),
        ("for i in range(8): pass", "8", "body", "index"),
        ("y = range(n, step=8)", "8", "body", ""),
        ("y = np.zeros(5)", "5", "body", "index"),
        ("y = np.zeros((3, 4))", "4", "body", "index"),
        ("y = np.full(shape, 2.5)", "2.5", "body", "index"),
        ("y = np.full(fill_value=2.5)", "2.5", "body", ""),
        ("y = rng.normal(0.5, 2.5, (3, 4))", "4", "body", "index"),
        ("y = rng.normal(0.5, 2.5, (3, 4))", "2.5", "body", ""),
        ("y = rng.normal(0.5, 2.5, size=7)", "7", "body", "index"),
        ("y = np.sum(x, axis=2)", "2", "body", "index"),
        ("y = np.std(x, ddof=2)", "2", "body", "index"),
        ("y = f(x, sigma=3.5)", "3.5", "body", ""),
        ("if len(x) > 3: pass", "3", "body", "index"),
        ("if x.shape[0] != 3: pass", "3", "body", "index"),
        ("if y > 3: pass", "3", "body", ""),
        ("n = len(x) // 2", "2", "body", "index"),
        ("n = 2 * x.size", "2", "body", "index"),
        ("n = len(x) * 2.0", "2.0", "body", "formula-coefficient"),  # a float is a quantity
        ("y = g(np.zeros(5) + 2.5)", "2.5", "body", ""),
        ("y = f(-(x[2]))", "2", "body", "index"),
        ("y = f(x)[2]", "2", "body", "index"),
        # sign and selection patterns
        ("CODE = [1, -1, 1, 1]", "-1", "module", "identity"),
        ("CODE = (0, 1)", "0", "module", "identity"),
        ("V = [1.0, 0.0]", "1.0", "module", ""),
        ("V = [1]", "1", "module", ""),
        ("V = [1, 2]", "1", "module", ""),
        # exponents
        ("y = x ** 2", "2", "module", "exponent"),
        ("y = x ** -2", "-2", "module", "exponent"),
        ("y = x ** 1.5", "1.5", "module", "exponent"),
        ("y = x ** 0.8", "0.8", "body", ""),
        ("y = x ** 4.5", "4.5", "body", ""),
        ("y = np.power(x, 0.5)", "0.5", "module", "exponent"),
        ("y = pow(x, 3)", "3", "module", "exponent"),
        ("y = np.power(x, 0.8)", "0.8", "module", ""),
        ("y = np.power(3, x)", "3", "module", ""),
        ("y = np.power(x, 3, out)", "3", "module", ""),
        ("y = 3 ** x", "3", "module", ""),
        # decibels
        ("y = 10 * np.log10(p)", "10", "module", "decibel"),
        ("y = 20 * np.log10(a)", "20", "module", "decibel"),
        ("y = -20 * np.log10(a)", "-20", "module", "decibel"),
        ("y = 10 ** (x / 10)", "10", "module", "decibel"),
        ("y = 10.0 ** (g / 20.0)", "20.0", "module", "decibel"),
        ("y = np.log10(x) + f(g(h(10)))", "10", "body", ""),  # too far from the log
        ("y = np.log10(x) + f(g(10))", "10", "body", "decibel"),
        ("y = p / 10", "10", "body", "formula-coefficient"),
        ("y = 20", "20", "module", ""),
        ("y = 30 * np.log10(x)", "30", "module", ""),
        # identities
        ("y = 1.0 - p", "1.0", "module", "identity"),
        ("y = -1.0 * p", "-1.0", "module", "identity"),
        ("y = 0.0", "0.0", "module", ""),
        ("y = 0.0", "0.0", "body", "identity"),
        ("y = f(1.0)", "1.0", "module", ""),
        ("y = f(1.0)", "1.0", "class", ""),
        ("y = f(-1)", "-1", "body", "identity"),
        # exact constructors
        ("h = Fraction(7, 3)", "7", "module", "exact-symbolic"),
        ("h = sp.Rational(7, 3)", "3", "module", "exact-symbolic"),
        ("s = sp.series(f, x, 0, 7)", "7", "module", "exact-symbolic"),
        ("s = comb(n, 5)", "5", "module", "exact-symbolic"),
        ("s = Fraction(numerator=7)", "7", "module", ""),
        # formula coefficients and conversions
        ("y = 8.0 / 27.0 * x", "8.0", "module", "formula-coefficient"),
        ("y = 8.0 / 27.0 * x", "27.0", "module", "formula-coefficient"),
        ("y = 16 / 13", "16", "module", "formula-coefficient"),
        ("y = 16.5 / 13", "13", "module", ""),
        ("y = 2.5 / 3", "3", "module", "formula-coefficient"),
        ("y = 2.5 / 3", "2.5", "module", "formula-coefficient"),
        ("y = x * 12", "12", "module", "formula-coefficient"),
        ("y = x * 13", "13", "module", ""),
        ("y = x * -12", "-12", "module", "formula-coefficient"),
        ("y = x / 2", "2", "module", "formula-coefficient"),
        ("y = x // 2", "2", "module", "formula-coefficient"),
        ("y = x % 7", "7", "module", "formula-coefficient"),
        ("y = x * 0.75", "0.75", "module", "formula-coefficient"),
        ("y = x * -0.25", "-0.25", "module", "formula-coefficient"),
        ("y = x * 0.3", "0.3", "module", ""),
        ("y = x / 60.0", "60.0", "module", "unit-conversion"),
        ("y = x * 86400", "86400", "module", "unit-conversion"),
        ("y = x * 360.0", "360.0", "module", "unit-conversion"),
        ("y = x * 1e-3", "1e-3", "module", "unit-conversion"),
        ("y = x * -1000.0", "-1000.0", "module", "unit-conversion"),
        ("y = x * 1e12", "1e12", "module", "unit-conversion"),
        ("y = x * 1e-12", "1e-12", "module", "unit-conversion"),
        ("y = x * 1e13", "1e13", "module", ""),
        ("y = x * 2e-3", "2e-3", "module", ""),
        ("y = x * 0.0", "0.0", "class", "identity"),
        ("y = x + 3", "3", "module", "formula-coefficient"),
        ("y = x - 12", "12", "module", "formula-coefficient"),
        ("y = x - 13", "13", "module", ""),
        ("y = x + 3.0", "3.0", "module", ""),
        ("y = x + 1000.0", "1000.0", "module", ""),
        ("y = x - 60.0", "60.0", "module", ""),
        ("y = x < 3", "3", "module", ""),
        ("y = x * 27000.0", "27000.0", "module", ""),
        ("def f(x=2):\n    pass", "2", "default", ""),
    ],
)
def test_classify_rule(source: str, literal: str, where: str, rule: str) -> None:
    """Oracle: each snippet read by hand against RULES (the rule named on its line)."""
    assert _rule(source, literal, where) == rule


def test_classify_rule_second_occurrence_and_bindings() -> None:
    """Oracle: the inner 10 of ``10 ** (x / 10)`` is also a decibel factor; a literal bound to
    a name with 'seed' in it is a seed, whatever it is; a binding without it changes nothing."""
    assert _rule("y = 10 ** (x / 10)", "10", "module", nth=1) == "decibel"
    assert _rule("y = 42", "42", "module", binding="master_SEED") == "seed"
    assert _rule("y = 42", "42", "module", binding="speed") == ""
    assert _rule("y = 1.0", "1.0", "module", binding="seed") == "seed"  # before identities


def test_claim_metadata_is_found_above_nested_arguments() -> None:
    """Oracle: a number inside a list argument of Claim(...) is still metadata; one inside a
    function called inside a function body is not (the def is the boundary)."""
    assert _rule("c = Claim(id='x', band=[2.5, 3.5])", "3.5", "module") == "claim-metadata"
    assert _rule("def f():\n    return g(2.5)\n", "2.5", "body") == ""
    src = "c = Claim(x=(lambda: 2.5))"
    assert _rule(src, "2.5", "module") == ""


# --- _identity_default ------------------------------------------------------------------------


def _default_of(src: str, param: str, value: float) -> bool:
    tree = ast.parse(textwrap.dedent(src))
    fn = tree.body[0]
    assert isinstance(fn, ast.FunctionDef)
    parents = {c: p for p in ast.walk(tree) for c in ast.iter_child_nodes(p)}
    return gate._identity_default(fn, param, value, parents)


@pytest.mark.parametrize(
    ("src", "param", "value", "identity"),
    [
        ("def f(x, scale=1.0):\n    return x * scale\n", "scale", 1.0, True),
        ("def f(x, scale=1):\n    return scale * x\n", "scale", 1, True),
        ("def f(x, scale=1.0):\n    return x / scale\n", "scale", 1.0, True),
        ("def f(x, scale=1.0):\n    return scale / x\n", "scale", 1.0, False),  # divides by x
        ("def f(x, scale=1.0):\n    return x + scale\n", "scale", 1.0, False),
        ("def f(x, scale=1.0):\n    return x * scale + scale\n", "scale", 1.0, False),
        ("def f(x, scale=1.0):\n    return g(scale)\n", "scale", 1.0, False),
        ("def f(x, scale=1.0):\n    return x\n", "scale", 1.0, False),  # never used
        ("def f(x, scale=1.0):\n    scale = 2.0\n    return x\n", "scale", 1.0, False),  # only stored
        ("def f(x, bias=0.0):\n    return x + bias\n", "bias", 0.0, False),  # 0 stays a candidate
        ("def f(x, bias=0.0):\n    return x - bias\n", "bias", 0.0, False),
        ("def f(x, gain=2.0):\n    return x * gain\n", "gain", 2.0, False),
        ("def f(x, scale=1.0):\n    return x * scale\n", "", 1.0, False),
    ],
)
def test_identity_default(src: str, param: str, value: float, identity: bool) -> None:
    """Oracle: a default of 1 is an identity only when every use multiplies by it or divides
    something by it; any other use, no use, or another value keeps it a candidate."""
    assert _default_of(src, param, value) is identity


# --- the index of a small package -------------------------------------------------------------

GIP = {
    "__init__.py": """
        from .model import far
    """,
    "consts.py": """
        R = 6371000.0
        FOOT = 0.3048
        TABLE = [2.5, 7.5]
        HALF = 1.0 / 2
        TWO_R = 2 * R
    """,
    "model.py": """
        import math

        import gip.consts as c
        from gip import consts
        from gip.consts import R
        from .consts import FOOT


        class Box:
            width: float = 4.5


        def area(x, scale=1.0, k=2.5):
            y = 0.47 * x
            return y * scale + k


        def far(x):
            return math.sqrt(R * x) + c.TABLE[1] + (
                consts.HALF * FOOT)


        len([8.5])
    """,
    "sub/__init__.py": "",
    "sub/m.py": """
        from ..consts import R as RADIUS

        Q = 9.5 * RADIUS
    """,
    "subtle.py": """
        Z = 11.5
    """,
    "cyc_a.py": """
        from gip.cyc_b import X
    """,
    "cyc_b.py": """
        from gip.cyc_a import X
    """,
    ".hidden/skip.py": "H = 99.5\n",
    "__pycache__/skip.py": "H = 98.5\n",
}

GIP_ALLOW = """
[[allow]]
file = "gip/consts.py"
name = "FOOT"
reason = "international foot, exact"
"""


@pytest.fixture(scope="module")
def gip(tmp_path_factory: pytest.TempPathFactory) -> Any:
    """The index of the ``gip`` package (never imported: the index only parses it)."""
    tmp = tmp_path_factory.mktemp("gip")
    _write_pkg(tmp / "gip", GIP)
    (tmp / "allow.toml").write_text(GIP_ALLOW)
    target = gate.Target(
        package="gip",
        root=tmp / "gip",
        claim_modules=lambda: [],
        repo=tmp,
        exclude={"sub": "a sub-package left out"},
        allowlist=tmp / "allow.toml",
    )
    return gate.index_package(target)


def _cands(index: Any, file: str) -> list[tuple[Any, ...]]:
    return sorted(
        (c.lineno, c.col, c.text, c.value, c.where, c.scope, c.binding, c.rule)
        for c in index.candidates
        if c.file == file
    )


def test_index_module_constants(gip: Any) -> None:
    """Oracle: consts.py read by hand (line, column, text, value, where, scope, binding, rule)."""
    assert _cands(gip, "gip/consts.py") == [
        (1, 4, "6371000.0", 6371000.0, "module", "<module>", "R", ""),
        (2, 7, "0.3048", 0.3048, "module", "<module>", "FOOT", ""),
        (3, 9, "2.5", 2.5, "module", "<module>", "TABLE", ""),
        (3, 14, "7.5", 7.5, "module", "<module>", "TABLE", ""),
        (4, 7, "1.0", 1.0, "module", "<module>", "HALF", "identity"),
        (4, 13, "2", 2, "module", "<module>", "HALF", "formula-coefficient"),
        (5, 8, "2", 2, "module", "<module>", "TWO_R", "formula-coefficient"),
    ]
    r = gip.candidate("gip/consts.py:1:4")
    assert r.id == "gip/consts.py:1:4" and r.module == "gip.consts"
    assert r.symbols == (("gip.consts", "R"),)
    assert r.position == (1, 4, 1, 13)
    assert r.line_text == "R = 6371000.0"
    assert r.allow is None
    assert gip.candidate("gip/consts.py:2:7").allow == {
        "file": "gip/consts.py",
        "name": "FOOT",
        "reason": "international foot, exact",
    }


def test_index_model_module(gip: Any) -> None:
    """Oracle: model.py read by hand; the default of 1 that area() only multiplies by is an
    identity, the other default (k, added) is a candidate."""
    assert _cands(gip, "gip/model.py") == [
        (10, 19, "4.5", 4.5, "class", "Box", "width", ""),
        (13, 18, "1.0", 1.0, "default", "area", "scale", "identity"),
        (13, 25, "2.5", 2.5, "default", "area", "k", ""),
        (14, 8, "0.47", 0.47, "body", "area", "y", ""),
        (19, 38, "1", 1, "body", "far", "", "index"),
        (23, 5, "8.5", 8.5, "module", "<module>", "", ""),
    ]
    box = gip.candidate("gip/model.py:10:19")
    assert box.symbols == (("gip.model", "Box"),)
    area = [f for f in gip.functions if f.qualname == "area"]
    far = [f for f in gip.functions if f.qualname == "far"]
    assert len(area) == 1 and len(far) == 1
    assert area[0].module == "gip.model" and area[0].top == ("gip.model", "area")
    assert gip.candidate("gip/model.py:13:18").function == area[0].id
    units = [gip.units[u] for u in area[0].units]
    assert [(u.lo, u.hi, u.file) for u in units] == [(14, 14, "gip/model.py"), (15, 15, "gip/model.py")]
    assert units[0].refs == {("y",), ("x",)}
    assert units[1].refs == {("y",), ("scale",), ("k",)}
    assert gip.candidate("gip/model.py:14:8").unit == units[0].id
    (far_unit,) = [gip.units[u] for u in far[0].units]
    assert (far_unit.lo, far_unit.hi) == (19, 20)
    # a dotted name is read with each of its prefixes
    assert far_unit.refs == {
        ("math",),
        ("math", "sqrt"),
        ("R",),
        ("x",),
        ("c",),
        ("c", "TABLE"),
        ("consts",),
        ("consts", "HALF"),
        ("FOOT",),
    }
    module_level = gip.candidate("gip/model.py:23:5")
    assert module_level.symbols == () and module_level.unit == -1


def test_index_bindings_and_dependencies(gip: Any) -> None:
    """Oracle: the import statements of model.py, the package's __init__ and sub/m.py (a
    relative import one and two levels up), and what each module constant is built from."""
    model = gip.modules["gip.model"]
    assert model.bindings == {
        "math": ("module", "math"),
        "c": ("module", "gip.consts"),
        "consts": ("from", "gip", "consts"),
        "R": ("from", "gip.consts", "R"),
        "FOOT": ("from", "gip.consts", "FOOT"),
        "Box": ("class",),
        "area": ("def",),
        "far": ("def",),
    }
    assert model.is_package is False and model.file == "gip/model.py"
    assert gip.modules["gip"].bindings == {"far": ("from", "gip.model", "far")}
    assert gip.modules["gip"].is_package is True
    assert gip.modules["gip.sub.m"].bindings == {"RADIUS": ("from", "gip.consts", "R"), "Q": ("value",)}
    consts = gip.modules["gip.consts"]
    assert consts.bindings == {n: ("value",) for n in ("R", "FOOT", "TABLE", "HALF", "TWO_R")}
    assert consts.deps["TWO_R"] == {("TWO_R",), ("R",)}
    assert consts.deps["HALF"] == {("HALF",)}


def test_index_excludes_modules_hidden_folders_and_caches(gip: Any) -> None:
    """Oracle: the ``sub`` prefix excludes gip.sub and gip.sub.m (their names stay indexed) but
    not gip.subtle; files under a dot-folder or __pycache__ are never read."""
    assert gip.excluded_modules == {
        "gip.sub": "a sub-package left out",
        "gip.sub.m": "a sub-package left out",
    }
    assert "gip.sub.m" in gip.modules
    assert not [c for c in gip.candidates if c.module.startswith("gip.sub.") or c.module == "gip.sub"]
    assert [c.text for c in gip.candidates if c.module == "gip.subtle"] == ["11.5"]
    assert sorted(gip.modules) == [
        "gip",
        "gip.consts",
        "gip.cyc_a",
        "gip.cyc_b",
        "gip.model",
        "gip.sub",
        "gip.sub.m",
        "gip.subtle",
    ]
    assert not [c for c in gip.candidates if c.value in (99.5, 98.5)]


def test_index_file_outside_the_repo_keeps_its_path(tmp_path: Path) -> None:
    """Oracle: a package outside ``repo`` names its files by their full path; no allowlist
    file means no entry."""
    _write_pkg(tmp_path / "p", {"a.py": "A = 3.5\n"})
    target = gate.Target(
        package="p", root=tmp_path / "p", claim_modules=list, repo=tmp_path / "elsewhere", allowlist=None
    )
    index = gate.index_package(target)
    (cand,) = index.candidates
    assert cand.file == str(tmp_path / "p" / "a.py")
    assert cand.id == f"{tmp_path / 'p' / 'a.py'}:1:4"
    assert cand.allow is None


SHAPES = """
import numpy as np
from dataclasses import dataclass

K = 3.25
TABLE = {}
for i, name in enumerate(["a", "b"]):
    TABLE[name] = K * 1.75
with open("f") as fh:
    DATA = fh.read()
try:
    import scipy
except ImportError:
    scipy = None


@dataclass
class Spec:
    gain: float = 6.5
    names: tuple = ("a",)

    def doubled(self, extra=0.25):
        return self.gain * 2.0 + extra


def outer(x, *, tol=1e-7):
    def inner(y, z=4.75):
        return y * 5.25

    class Local(Base, size=9.25):
        rate = 1.25

    f = lambda t, u=0.125: t * 6.75
    try:
        v = inner(x)
    except (KeyError, 3.5):
        v = 8.25
    match x:
        case 2.75 if x > 0.375:
            pass
    while x < 13.5:
        break
    return f(v)


CLAIMS = [lambda: outer(2.125)]
"""


@pytest.fixture(scope="module")
def shapes(tmp_path_factory: pytest.TempPathFactory) -> Any:
    tmp = tmp_path_factory.mktemp("shapes")
    _write_pkg(tmp / "sp", {"__init__.py": "", "shapes.py": SHAPES})
    return gate.index_package(gate.Target(package="sp", root=tmp / "sp", claim_modules=list, repo=tmp))


def test_index_statement_kinds(shapes: Any) -> None:
    """Oracle: SHAPES read by hand (its first line is ``import numpy``): each literal's line,
    where, scope, binding and rule (a loop body at module level, a dataclass field and a method
    default, nested defs, a class and a lambda in a function, an except clause, a match case and
    its guard, a while test, a claim's lambda)."""
    got = sorted((c.lineno, c.text, c.where, c.scope, c.binding, c.rule) for c in shapes.candidates)
    assert got == [
        (4, "3.25", "module", "<module>", "K", ""),
        (7, "1.75", "module", "<module>", "", ""),
        (18, "6.5", "class", "Spec", "gain", ""),
        (21, "0.25", "default", "Spec.doubled", "extra", ""),
        (22, "2.0", "body", "Spec.doubled", "", "formula-coefficient"),
        (25, "1e-7", "default", "outer", "tol", ""),
        (26, "4.75", "body", "outer", "z", ""),  # a nested def's default runs in its outer body
        (27, "5.25", "body", "outer.inner", "", ""),
        (29, "9.25", "body", "outer", "size", "index"),  # a class keyword named size
        (30, "1.25", "body", "outer.Local", "rate", ""),
        (32, "0.125", "body", "outer", "u", ""),  # a lambda's default: made in the outer body
        (32, "6.75", "body", "outer.<lambda:32>", "", ""),
        (35, "3.5", "body", "outer", "", ""),
        (36, "8.25", "body", "outer", "v", ""),
        (38, "0.375", "body", "outer", "", ""),
        (38, "2.75", "body", "outer", "", ""),
        (40, "13.5", "body", "outer", "", ""),
        (45, "2.125", "body", "<module>.<lambda:45>", "", ""),
    ]


def test_index_loop_and_units(shapes: Any) -> None:
    """Oracle: SHAPES by hand. What the module-level loop builds (TABLE) also depends on what it
    iterates (its targets i and name); a later ``scipy = None`` keeps the import's binding; a
    nested def's defaults are a unit of the outer function; a try's unit is its except clause's
    type, a match's its subject, case pattern and guard; the claim's lambda is a function."""
    info = shapes.modules["sp.shapes"]
    assert info.deps["TABLE"] == {("TABLE",), ("K",), ("i",), ("name",)}
    assert info.deps["i"] == {("enumerate",), ("i",), ("name",)}
    assert info.deps["DATA"] == {("DATA",), ("fh",), ("fh", "read")}
    assert info.deps["Spec"] == {("dataclass",), ("gain",), ("names",)}
    assert info.deps["K"] == {("K",)}
    assert info.bindings == {
        "np": ("module", "numpy"),
        "dataclass": ("from", "dataclasses", "dataclass"),
        "K": ("value",),
        "TABLE": ("value",),
        "i": ("value",),
        "name": ("value",),
        "fh": ("value",),
        "DATA": ("value",),
        "scipy": ("module", "scipy"),
        "Spec": ("class",),
        "outer": ("def",),
        "CLAIMS": ("value",),
    }
    funcs = [(f.qualname, f.top) for f in shapes.functions]
    assert funcs == [
        ("Spec.doubled", ("sp.shapes", "Spec")),
        ("outer", ("sp.shapes", "outer")),
        ("outer.inner", ("sp.shapes", "outer")),
        ("outer.<lambda:32>", ("sp.shapes", "outer")),
        ("<module>.<lambda:45>", None),
    ]

    def spans(f: Any) -> list[tuple[int, int, set[Any]]]:
        return [(shapes.units[u].lo, shapes.units[u].hi, shapes.units[u].refs) for u in f.units]

    doubled, outer, inner, lam, claim = shapes.functions
    assert spans(doubled) == [(22, 22, {("self",), ("self", "gain"), ("extra",)})]
    assert spans(outer) == [
        (26, 26, set()),  # def inner(y, z=4.75): its default
        (29, 30, {("Base",)}),  # class Local(Base, size=9.25): the class statement
        (30, 30, {("rate",)}),
        (32, 32, {("f",)}),
        (35, 35, {("KeyError",)}),  # try: the except clause's type
        (34, 34, {("v",), ("inner",), ("x",)}),
        (36, 36, {("v",)}),
        (37, 38, {("x",)}),  # match x: case 2.75 if x > 0.375
        (39, 39, set()),  # pass
        (40, 40, {("x",)}),
        (41, 41, set()),  # break
        (42, 42, {("f",), ("v",)}),
    ]
    assert spans(inner) == [(27, 27, {("y",)})]
    assert spans(lam) == [(32, 32, {("t",)})]
    assert spans(claim) == [(45, 45, {("outer",)})]
    assert all(f.header_refs == set() for f in shapes.functions)
    assert {shapes.units[u].function for u in outer.units} == {outer.id}
    assert shapes.candidate(f"{shapes.candidates[0].file}:25:20").function == outer.id


# --- allowlist --------------------------------------------------------------------------------


def test_load_allowlist(tmp_path: Path) -> None:
    """Oracle: no file means no entries; a complete entry is returned as written; an entry
    without its file, without a name or text, or with a blank reason is refused."""
    assert gate.load_allowlist(None) == []
    assert gate.load_allowlist(tmp_path / "missing.toml") == []
    good = tmp_path / "good.toml"
    good.write_text('[[allow]]\nfile = "a.py"\ntext = "0.5"\nscope = "f"\nreason = "exact"\n')
    assert gate.load_allowlist(good) == [{"file": "a.py", "text": "0.5", "scope": "f", "reason": "exact"}]
    empty = tmp_path / "empty.toml"
    empty.write_text("")
    assert gate.load_allowlist(empty) == []
    for body in (
        'name = "X"\nreason = "r"',
        'file = "a.py"\nreason = "r"',
        'file = "a.py"\nname = "X"',
        'file = "a.py"\nname = "X"\nreason = "  "',
        'file = ""\nname = "X"\nreason = "r"',
    ):
        bad = tmp_path / "bad.toml"
        bad.write_text(f"[[allow]]\n{body}\n")
        with pytest.raises(ValueError, match="needs a file, a name or text, and a reason"):
            gate.load_allowlist(bad)


def _cand(**kw: Any) -> Any:
    base: dict[str, Any] = dict(
        id="p/a.py:1:4",
        module="p.a",
        file="p/a.py",
        lineno=1,
        col=4,
        end_lineno=1,
        end_col=7,
        value=0.5,
        text="0.5",
        line_text="X = 0.5",
        scope="<module>",
        where="module",
        binding="X",
    )
    base.update(kw)
    return gate.Candidate(**base)


def test_allowed_matches_file_name_text_and_scope() -> None:
    """Oracle: an entry applies when its file matches and each of name, text and scope it gives
    matches too; the first matching entry wins."""
    c = _cand()
    by_name = {"file": "p/a.py", "name": "X", "reason": "r1"}
    by_text = {"file": "p/a.py", "text": "0.5", "scope": "<module>", "reason": "r2"}
    assert gate._allowed(c, [by_name, by_text]) is by_name
    assert gate._allowed(c, [by_text, by_name]) is by_text
    assert gate._allowed(c, [{"file": "p/b.py", "name": "X", "reason": "r"}]) is None
    assert gate._allowed(c, [{"file": "p/a.py", "name": "Y", "reason": "r"}]) is None
    assert gate._allowed(c, [{"file": "p/a.py", "text": "0.50", "reason": "r"}]) is None
    assert gate._allowed(c, [{"file": "p/a.py", "text": "0.5", "scope": "f", "reason": "r"}]) is None
    other = {"file": "p/a.py", "name": "Y", "reason": "r"}
    assert gate._allowed(c, [other, by_text]) is by_text
    assert gate._allowed(c, []) is None


def test_module_name() -> None:
    """Oracle: a package's __init__ is the package; another file is its dotted path."""
    root = Path("/x/pkg")
    assert gate._module_name("pkg", root, root / "__init__.py") == ("pkg", True)
    assert gate._module_name("pkg", root, root / "a" / "__init__.py") == ("pkg.a", True)
    assert gate._module_name("pkg", root, root / "a" / "b.py") == ("pkg.a.b", False)


# --- name resolution and relevance -------------------------------------------------------------


def test_resolver(gip: Any) -> None:
    """Oracle: GIP's imports by hand: from-imports, module aliases, a package's submodule, a
    relative import, a chain through the package's __init__, unbound and third-party names,
    an import cycle."""
    r = gate.Resolver(gip)
    assert r.resolve("gip.model", ("R",)) == (("gip.consts", "R"),)
    assert r.resolve("gip.model", ("FOOT",)) == (("gip.consts", "FOOT"),)
    assert r.resolve("gip.model", ("c", "TABLE")) == (("gip.consts", "TABLE"),)
    assert r.resolve("gip.model", ("consts", "HALF")) == (("gip.consts", "HALF"),)
    assert r.resolve("gip.model", ("consts", "HALF", "real")) == (("gip.consts", "HALF"),)
    assert r.resolve("gip.model", ("c",)) == ()  # a module, not a symbol
    assert r.resolve("gip.model", ("math", "sqrt")) == ()
    assert r.resolve("gip.model", ("x",)) == ()
    assert r.resolve("gip.model", ("area",)) == (("gip.model", "area"),)
    assert r.resolve("gip", ("far",)) == (("gip.model", "far"),)
    assert r.resolve("gip", ("consts", "R")) == (("gip.consts", "R"),)  # a submodule by name
    assert r.resolve("gip", ("nothing",)) == ()
    assert r.resolve("gip.sub.m", ("RADIUS",)) == (("gip.consts", "R"),)
    assert r.resolve("gip.consts", ("consts",)) == ()  # not a package: no submodule lookup
    assert r.resolve("gip.cyc_a", ("X",)) == ()
    assert r.resolve("nowhere", ("X",)) == ()
    assert r.resolve("gip.model", ("R",)) is r.resolve("gip.model", ("R",))  # cached


def test_resolver_binding_kinds(gip: Any) -> None:
    """Oracle: the _binding of each kind of name in GIP by hand."""
    r = gate.Resolver(gip)
    assert r._binding("gip.model", "c") == ("module", "gip.consts")
    assert r._binding("gip.model", "consts") == ("module", "gip.consts")
    assert r._binding("gip.model", "math") is None
    assert r._binding("gip.model", "R") == ("symbol", "gip.consts", "R")
    assert r._binding("gip", "sub") == ("module", "gip.sub")
    assert r._binding("gip", "model") == ("module", "gip.model")
    assert r._binding("gip.model", "R", depth=21) is None
    assert r._binding("gip.sub.m", "RADIUS", depth=19) == ("symbol", "gip.consts", "R")
    assert r._binding("gip.cyc_a", "X") is None


def test_resolver_closure(gip: Any) -> None:
    """Oracle: TWO_R = 2 * R is built from R; HALF from nothing else; an unknown module's symbol
    is kept as it is."""
    r = gate.Resolver(gip)
    assert r.closure([("gip.consts", "TWO_R")]) == {("gip.consts", "TWO_R"), ("gip.consts", "R")}
    assert r.closure([("gip.consts", "HALF")]) == {("gip.consts", "HALF")}
    assert r.closure([("nope", "X"), ("nope", "X")]) == {("nope", "X")}
    assert r.closure([]) == set()


def test_relevance(gip: Any) -> None:
    """Oracle: three hand-written traces of GIP. c1 ran area's two lines, c2 only the second line
    of far's two-line return, c3 only area's def line (no unit); which literal each claim can
    move follows by hand from the module doc's rules."""
    traces = {
        "c1": {"lines": {"gip/model.py": [14, 15]}},
        "c2": {"lines": {"gip/model.py": [20], "gip/other.py": [1]}},
        "c3": {"lines": {"gip/model.py": [13, 16, 21]}},
        "c4": {},
    }
    rel = gate.relevance(gip, traces, gip.candidates)
    by_text = {(c.file, c.text): rel.claims_of[c.id] for c in gip.candidates}
    assert by_text == {
        ("gip/consts.py", "6371000.0"): {"c2"},
        ("gip/consts.py", "0.3048"): {"c2"},
        ("gip/consts.py", "2.5"): {"c2"},
        ("gip/consts.py", "7.5"): {"c2"},
        ("gip/consts.py", "1.0"): {"c2"},
        ("gip/consts.py", "2"): set(),  # HALF's 2 and TWO_R's 2: the one listed last wins here
        ("gip/model.py", "4.5"): set(),
        ("gip/model.py", "1.0"): {"c1"},
        ("gip/model.py", "2.5"): {"c1"},
        ("gip/model.py", "0.47"): {"c1"},
        ("gip/model.py", "1"): {"c2"},
        ("gip/model.py", "8.5"): {"c1", "c2"},
        ("gip/subtle.py", "11.5"): set(),
    }
    half_2 = gip.candidate("gip/consts.py:4:13")
    assert rel.claims_of[half_2.id] == {"c2"}
    area, far = gip.functions
    assert rel.units_run == {"c1": set(area.units), "c2": set(far.units), "c3": set(), "c4": set()}
    assert rel.used["c1"] == {("gip.model", "area")}
    assert rel.used["c2"] == {
        ("gip.model", "far"),
        ("gip.consts", "R"),
        ("gip.consts", "TABLE"),
        ("gip.consts", "HALF"),
        ("gip.consts", "FOOT"),
    }
    assert rel.used["c3"] == set()


def test_relevance_of_a_lone_module_literal_and_header_refs(tmp_path: Path) -> None:
    """Oracle: a decorated function's decorator argument is read when it is made (its header):
    a claim that ran the function uses the decorator's name; a literal at module level outside
    any binding applies to every claim that ran code of its module."""
    _write_pkg(
        tmp_path / "q",
        {
            "__init__.py": "",
            "a.py": """
                LIMIT = 4.5


                @deco(LIMIT)
                def f(x):
                    return x


                print(5.5)
            """,
        },
    )
    index = gate.index_package(
        gate.Target(package="q", root=tmp_path / "q", claim_modules=list, repo=tmp_path)
    )
    (f,) = index.functions
    assert f.header_refs == {("deco",), ("LIMIT",)}
    rel = gate.relevance(index, {"k": {"lines": {"q/a.py": [6]}}}, index.candidates)
    assert {c.text: rel.claims_of[c.id] for c in index.candidates} == {"4.5": {"k"}, "5.5": {"k"}}
    assert rel.used["k"] == {("q.a", "f"), ("q.a", "LIMIT")}


# --- the children's work, in this process -------------------------------------------------------

GIC = {
    "__init__.py": "",
    "model.py": """
        def drag(v):
            return 0.47 * v


        def horizon(h):
            return (2.0 * 6371000.0 * h) ** 0.5
    """,
    "claims.py": """
        from navcore.ledger import EXACT, Claim, InputSet, printed
        from gic import model

        IN = InputSet("WF", "gate_inprocess")
        IN.published("v", 3.0, locator="Table 1", unit="m/s")


        def _h():
            return model.horizon(100.0)


        def _c(cid, text, compute):
            value, tol = printed(text)
            return Claim(id=cid, paper="WF", locator="Table 1", quantity="q", published=value, unit="m",
                         compute=compute, tolerance=tol, expected_status="reproduced", note="synthetic")


        CLAIMS = [
            _c("WF-gic-drag", "1.41", lambda: model.drag(IN.v)),
            Claim(id="WF-gic-statement", paper="WF", locator="Table 1", quantity="s", published=True,
                  unit="statement", compute=lambda: _h() > 35000.0, tolerance=EXACT,
                  expected_status="reproduced", note="synthetic"),
            _c("WF-gic-fails", "1.0", lambda: model.drag(IN.v) / 0.0),
        ]
    """,
}
HORIZON = math.sqrt(2.0 * 6371000.0 * 100.0)  # 35695.94 m


def _forget(prefix: str) -> None:
    for name in [m for m in sys.modules if m == prefix or m.startswith(prefix + ".")]:
        del sys.modules[name]


@pytest.fixture
def gic(tmp_path: Path) -> Any:
    """The claims package on sys.path for one test; afterwards its modules, its registered input
    and the gate's import hook are gone again."""
    from navcore.claims import inputs

    _write_pkg(tmp_path / "gic", GIC)
    sys.path.insert(0, str(tmp_path))
    meta_path = list(sys.meta_path)
    try:
        yield gate.Target(
            package="gic",
            root=tmp_path / "gic",
            claim_modules=lambda: ["gic.claims"],
            repo=tmp_path,
            exposure_prefix="gic.claims",
        )
    finally:
        sys.path.remove(str(tmp_path))
        sys.meta_path[:] = meta_path
        gate._PerturbedLoader.spots = {}
        _forget("gic")
        inputs._REGISTRY.pop("WF.gate_inprocess.v", None)
        sys.setprofile(None)


def test_claims_metadata(gic: Any) -> None:
    """Oracle: the three claims as written: printed("1.41") allows half a unit of its last digit
    (0.005), a statement allows nothing; the package is not third-party, navcore is."""
    out = gate.claims_metadata(gic)
    drag = out["claims"]["WF-gic-drag"]
    assert drag == {
        "paper": "WF",
        "module": "gic.claims",
        "published": 1.41,
        "statement": False,
        "computes": True,
        "allowed": pytest.approx(0.005),
        "policy": "printed-digits",
        "relation": "=",
        "unit": "m",
        "quantity": "q",
    }
    stmt = out["claims"]["WF-gic-statement"]
    assert stmt["published"] is True and stmt["statement"] is True and stmt["allowed"] == 0.0
    assert list(out["claims"]) == ["WF-gic-drag", "WF-gic-statement", "WF-gic-fails"]
    assert "navcore.ledger" in out["third_party"]
    assert not [m for m in out["third_party"] if m == "gic" or m.startswith("gic.")]
    assert "__main__" not in out["third_party"]
    assert out["third_party"] == sorted(out["third_party"])


def test_claims_metadata_keeps_a_claim_whose_tolerance_fails(gic: Any) -> None:
    """Oracle: a tolerance that raises is reported as NaN with the error, not raised."""

    class Bad:
        id = "X-bad"
        paper = "X"
        published = 2.0
        is_statement = False
        compute = None
        relation = "="
        unit = ""
        quantity = "q"

        def tolerance(self) -> None:
            raise RuntimeError("no tolerance")

    target = gate.Target(package="gic", root=gic.root, claim_modules=lambda: ["fakeclaims"], repo=gic.repo)
    fake = type(sys)("fakeclaims")
    fake.CLAIMS = [Bad()]  # type: ignore[attr-defined]
    sys.modules["fakeclaims"] = fake
    try:
        meta = gate.claims_metadata(target)["claims"]["X-bad"]
    finally:
        del sys.modules["fakeclaims"]
    assert math.isnan(meta["allowed"]) and meta["policy"].startswith("error: ")
    assert meta["computes"] is False and meta["module"] == "fakeclaims"


def test_trace_claim(gic: Any) -> None:
    """Oracle: claims.py and model.py by hand: drag(3.0) = 0.47 * 3.0 = 1.41 reading input v
    (3.0); the lines run are the claim's lambda (line 19 of claims.py) and drag's body (line 2
    of model.py); the statement runs _h (line 9), its lambda (line 21) and horizon (line 6) and
    records what _h returns, sqrt(2 * 6371000 * 100)."""
    out = gate.trace_claim(gic, "WF-gic-drag")
    assert out["value"] == pytest.approx(1.41) and out["error"] is None
    assert out["reads"] == {"WF.gate_inprocess.v": "3.0"}
    assert out["exposures"] is None
    assert out["lines"] == {"gic/claims.py": [19], "gic/model.py": [2]}
    assert out["seconds"] >= 0.0
    st = gate.trace_claim(gic, "WF-gic-statement")
    assert st["value"] is True and st["reads"] == {}
    assert st["exposures"] == {"_h": [pytest.approx(HORIZON)]}
    assert st["lines"] == {"gic/claims.py": [9, 21], "gic/model.py": [6]}
    bad = gate.trace_claim(gic, "WF-gic-fails")
    assert bad["value"] is None and bad["reads"] == {}
    assert bad["error"] == "ZeroDivisionError: float division by zero"


def test_evaluate_perturbed_rewrites_a_literal_at_import(gic: Any) -> None:
    """Oracle: drag's 0.47 (model.py line 2, columns 11-15) rewritten to 0.5 gives 0.5 * 3.0 =
    1.5; 6371000.0 (line 6, columns 18-27) rewritten to 4 * 6371000.0 doubles the horizon; with a
    stop that is always true only the first claim is evaluated."""
    out = gate.evaluate_perturbed(
        gic,
        {"gic.model": {(2, 11, 2, 15): 0.5, (6, 18, 6, 27): 4 * 6371000.0}},
        ["WF-gic-drag", "WF-gic-statement"],
        ["gic.claims"],
    )
    assert out["WF-gic-drag"]["value"] == pytest.approx(1.5)
    assert out["WF-gic-statement"]["exposures"] == {"_h": [pytest.approx(2 * HORIZON)]}
    _forget("gic")
    seen: list[str] = []

    def stop(cid: str, result: dict) -> bool:
        seen.append(cid)
        return result["value"] is not None

    out = gate.evaluate_perturbed(
        gic, {}, ["WF-gic-fails", "WF-gic-drag", "WF-gic-statement"], ["gic.claims"], stop
    )
    assert list(out) == ["WF-gic-fails", "WF-gic-drag"] and seen == ["WF-gic-fails", "WF-gic-drag"]
    assert out["WF-gic-drag"]["value"] == pytest.approx(1.41)  # unperturbed: nothing left over


def test_evaluate_perturbed_refuses_a_literal_it_cannot_find(gic: Any) -> None:
    """Oracle: model.py has no literal at line 9, so the rewrite must fail loudly."""
    with pytest.raises(RuntimeError, match=r"literals not found in gic.model: \[\(9, 0, 9, 3\)\]"):
        gate.evaluate_perturbed(gic, {"gic.model": {(9, 0, 9, 3): 1.0}}, ["WF-gic-drag"], ["gic.claims"])


def test_replace_and_finder() -> None:
    """Oracle: ``x = 2.5 + -1.5`` with -1.5 (columns 10-14) replaced by 7.0 evaluates to 9.5;
    the finder ignores a module it has no spots for."""
    tree = ast.parse("x = 2.5 + -1.5")
    rep = gate._Replace({(1, 10, 1, 14): 7.0})
    tree = ast.fix_missing_locations(rep.visit(tree))
    ns: dict[str, Any] = {}
    exec(compile(tree, "<t>", "exec"), ns)
    assert ns["x"] == 9.5 and rep.found == {(1, 10, 1, 14)}
    gate._PerturbedLoader.spots = {}
    assert gate._PerturbedFinder().find_spec("json", None) is None
    gate._PerturbedLoader.spots = {"no_such_module_here": {}}
    try:
        assert gate._PerturbedFinder().find_spec("no_such_module_here", None) is None
    finally:
        gate._PerturbedLoader.spots = {}


def test_exposure_records_only_floats_returned_between_paper_functions() -> None:
    """Oracle: a profile function fed hand-made frames: a float (or a 0-d array) returned by a
    paper function to a paper function is recorded under its qualname; a return to another
    module, a non-number, a call event or another module's function is not."""
    import numpy as np

    class Code:
        def __init__(self, qual: str, name: str = "f") -> None:
            self.co_qualname = qual
            self.co_name = name

    class Frame:
        def __init__(self, module: str, qual: str, back: Any = None, name: str = "f", loc: Any = None):
            self.f_globals = {"__name__": module}
            self.f_code = Code(qual, name)
            self.f_back = back
            self.f_locals = loc or {}

    paper = Frame("pp.a", "caller")
    other = Frame("numpy", "caller")
    expo = gate._Exposure("pp.")
    expo(Frame("pp.b", "g", paper), "return", 2.5)
    expo(Frame("pp.b", "g", paper), "return", np.float64(3.5))
    expo(Frame("pp.b", "g", paper), "return", np.array(4.5))
    expo(Frame("pp.b", "g", paper), "return", np.array([1.0]))  # not a scalar
    expo(Frame("pp.b", "g", paper), "return", 7)  # an int is not recorded
    expo(Frame("pp.b", "g", paper), "call", 5.5)
    expo(Frame("pp.b", "g", other), "return", 6.5)
    expo(Frame("pp.b", "g", None), "return", 6.5)
    expo(Frame("lib.c", "h", paper), "return", 8.5)

    def memo() -> None:
        pass

    memo.__module__ = "pp.b"
    memo.__qualname__ = "memoised"
    wrapper = Frame("navcore.claims.inputs", "input_cache.<locals>.wrapper", paper, "wrapper", {"fn": memo})
    expo(wrapper, "return", 9.5)
    lib_fn = Frame("navcore.claims.inputs", "w", paper, "wrapper", {"fn": len})
    expo(lib_fn, "return", 10.5)
    not_wrapper = Frame("navcore.claims.inputs", "other", paper, "other", {"fn": memo})
    expo(not_wrapper, "return", 11.5)
    assert dict(expo.values) == {"g": [2.5, 3.5, 4.5], "memoised": [9.5]}
    assert expo.n == 4
    full = gate._Exposure("pp.")
    full.n = 20000
    full(Frame("pp.b", "g", paper), "return", 2.5)
    assert dict(full.values) == {}
    almost = gate._Exposure("pp.")
    almost.n = 19999
    almost(Frame("pp.b", "g", paper), "return", 2.5)
    assert dict(almost.values) == {"g": [2.5]}


def test_canonical() -> None:
    """Oracle: JSON of the ledger's plain form, keys sorted; an object JSON cannot hold is its
    repr."""
    import numpy as np

    assert gate._canonical(1.5) == "1.5"
    assert gate._canonical({"b": 1, "a": [2.0, 3]}) == '{"a": [2.0, 3], "b": 1}'
    assert gate._canonical(np.array([1.0, 2.0])) == "[1.0, 2.0]"
    from navcore.claims.json_coding import jsonable

    assert gate._canonical(float("nan")) == json.dumps(jsonable(float("nan")))

    class Odd:
        def __repr__(self) -> str:
            return "<odd>"

    assert gate._canonical({"x": Odd()}) == '{"x": "<odd>"}'


# --- compare and Effect -----------------------------------------------------------------------

NUM = {"statement": False, "allowed": 0.5, "published": 100.0}
STMT = {"statement": True, "allowed": 0.0, "published": True}


def _res(
    value: Any, reads: dict | None = None, error: str | None = None, exposures: dict | None = None
) -> dict:
    return {"value": value, "reads": reads or {}, "error": error, "exposures": exposures}


def test_compare_numeric() -> None:
    """Oracle: a change of 0.25 against a tolerance of 0.5 is half a tolerance; the inputs whose
    recorded values differ (or exist on one side only) are listed, sorted."""
    eff = gate.compare(NUM, _res(100.0, {"a": "1", "b": "2"}), _res(100.25, {"a": "1", "b": "3", "c": "4"}))
    assert eff.tolerances == pytest.approx(0.5)
    assert eff.inputs_changed == ("b", "c")
    assert eff.flipped is False and eff.error is None and eff.exposure_rel == 0.0
    assert gate.compare(NUM, _res(100.0), _res(99.0)).tolerances == pytest.approx(2.0)


def test_compare_exact_claim_uses_a_floor() -> None:
    """Oracle: with no tolerance, a change is judged against 1e-9 of the larger of the value and
    the published number: 100 -> 100 + 1e-6 is 1e-6 / 1e-7 = 10 tolerances; a tolerance smaller
    than the floor is replaced by it; a NaN tolerance too."""
    exact = {"statement": False, "allowed": 0.0, "published": 100.0}
    assert gate.compare(exact, _res(100.0), _res(100.0 + 1e-6)).tolerances == pytest.approx(10.0, rel=1e-6)
    tiny = {**exact, "allowed": 1e-12}
    assert gate.compare(tiny, _res(100.0), _res(100.0 + 1e-6)).tolerances == pytest.approx(10.0, rel=1e-6)
    nan = {**exact, "allowed": float("nan")}
    assert gate.compare(nan, _res(100.0), _res(100.0 + 1e-6)).tolerances == pytest.approx(10.0, rel=1e-6)
    big_pub = {**exact, "published": 1000.0}  # the published number sets the floor: 1e-6
    assert gate.compare(big_pub, _res(100.0), _res(100.0 + 1e-6)).tolerances == pytest.approx(1.0, rel=1e-6)
    big_val = {**exact, "published": 1.0}  # the value sets it: 1e-7
    assert gate.compare(big_val, _res(100.0), _res(100.0 + 1e-6)).tolerances == pytest.approx(10.0, rel=1e-6)
    zero = {**exact, "published": 0.0}
    # a zero published and nominal value: the floor is 1e-9 of 1e-300
    assert gate.compare(zero, _res(0.0), _res(1e-300)).tolerances == pytest.approx(1e9)
    just_above = {**exact, "allowed": 2e-7}  # above the floor of 1e-7: used
    assert gate.compare(just_above, _res(100.0), _res(100.0 + 1e-6)).tolerances == pytest.approx(
        5.0, rel=1e-6
    )
    inf = {**exact, "allowed": math.inf}
    assert gate.compare(inf, _res(100.0), _res(100.0 + 1e-6)).tolerances == pytest.approx(10.0, rel=1e-6)


def test_compare_errors_and_missing_values() -> None:
    """Oracle: a perturbed error is the effect unless the nominal run failed too; a missing value
    compares as no change; non-finite values move infinitely unless both are the same."""
    eff = gate.compare(NUM, _res(1.0), _res(None, error="ValueError: x"))
    assert eff.error == "ValueError: x" and eff.moved(1e9, 1e9)
    both = gate.compare(NUM, _res(None, error="E"), _res(None, error="E2"))
    assert both.error is None and not both.moved(0.0, 0.0)
    assert gate.compare(NUM, _res(None), _res(1.0)).tolerances == 0.0
    assert gate.compare(NUM, _res(1.0), _res(None)).tolerances == 0.0
    assert gate.compare(NUM, _res(1.0), _res(math.inf)).tolerances == math.inf
    assert gate.compare(NUM, _res(math.inf), _res(1.0)).tolerances == math.inf
    assert gate.compare(NUM, _res(math.inf), _res(math.inf)).tolerances == 0.0
    assert gate.compare(NUM, _res(math.nan), _res(math.nan)).tolerances == 0.0
    assert gate.compare(NUM, _res(math.nan), _res(1.0)).tolerances == math.inf
    assert gate.compare(NUM, _res(1.0, {"a": "1"}), _res(math.inf, {"a": "2"})).inputs_changed == ("a",)


def test_compare_statements() -> None:
    """Oracle: a statement flips when its truth changes; its numbers' largest relative change,
    judged function by function and call by call, is |b - a| / max(|a|, |b|); a function called
    another number of times is not compared; a non-finite number counts as a change of 1."""
    e0 = {"f": [100.0, 50.0], "g": [1.0], "h": [2.0, 3.0], "only0": [1.0]}
    e1 = {"f": [101.0, 50.0], "g": [1.0], "h": [4.0], "only1": [9.0]}
    eff = gate.compare(STMT, _res(True, exposures=e0), _res(True, exposures=e1))
    assert eff.flipped is False
    assert eff.exposure_rel == pytest.approx(1.0 / 101.0)
    assert eff.tolerances == 0.0
    eff = gate.compare(STMT, _res(True, exposures={"f": [-2.0]}), _res(False, exposures={"f": [-1.0]}))
    assert eff.flipped is True and eff.exposure_rel == pytest.approx(0.5)
    eff = gate.compare(STMT, _res(1, exposures={"f": [1.0]}), _res(True, exposures={"f": [math.nan]}))
    assert eff.flipped is False and eff.exposure_rel == 1.0
    eff = gate.compare(
        STMT, _res(True, exposures={"f": [math.inf, 0.5]}), _res(True, exposures={"f": [math.inf, 0.25]})
    )
    assert eff.exposure_rel == pytest.approx(0.5)  # equal infinities are no change
    eff = gate.compare(STMT, _res(True, exposures={"f": [0.0]}), _res(True, exposures={"f": [1e-310]}))
    assert eff.exposure_rel == pytest.approx(1e-10)  # judged against 1e-300, not 0
    eff = gate.compare(STMT, _res(True), _res(True, exposures={"f": [1.0]}))
    assert eff.exposure_rel == 0.0 and not eff.moved(0.0, 0.0)
    eff = gate.compare(STMT, _res(True, {"a": "1"}), _res(True, {"a": "1"}))
    assert eff.inputs_changed == ()


def test_effect_moved() -> None:
    """Oracle: the definition: an error, a flip, or more than either threshold (strictly)."""
    assert not gate.Effect().moved(0.0, 0.0)
    assert gate.Effect(error="x").moved(1.0, 1.0)
    assert gate.Effect(flipped=True).moved(1.0, 1.0)
    assert gate.Effect(tolerances=1.5).moved(1.0, 9.0)
    assert not gate.Effect(tolerances=1.0).moved(1.0, 9.0)
    assert gate.Effect(exposure_rel=1.5).moved(9.0, 1.0)
    assert not gate.Effect(exposure_rel=1.0).moved(9.0, 1.0)


# --- perturbation values ----------------------------------------------------------------------


def test_perturbed_value() -> None:
    """Oracle: x (1 +- magnitude * rel) by hand; integers round, and move by one at least; a
    float zero moves by ZERO_STEP scaled like the relative step."""
    assert gate.perturbed_value(2.0, +1) == pytest.approx(2.002)
    assert gate.perturbed_value(2.0, -1, 0.5) == pytest.approx(1.999)
    assert gate.perturbed_value(2.0, +1, 1.0, rel=0.1) == pytest.approx(2.2)
    assert gate.perturbed_value(27000, -1) == 26973
    assert gate.perturbed_value(27000, +1, 0.5) == 27014  # 27013.5 rounds to even
    assert gate.perturbed_value(8, +1) == 9
    assert gate.perturbed_value(8, -1) == 7
    assert gate.perturbed_value(8, -1, rel=0.5) == 4
    assert gate.perturbed_value(0.0, -1) == -gate.ZERO_STEP
    assert gate.perturbed_value(0.0, +1, 0.5) == pytest.approx(0.5 * gate.ZERO_STEP)
    assert gate.perturbed_value(0.0, +1, 1.0, rel=0.1) == pytest.approx(0.1)
    assert gate.perturbed_value(0, +1) == 1
    assert gate.perturbed_value(0, -1) == -1
    assert isinstance(gate.perturbed_value(8, +1), int)


def test_times_and_probe_size() -> None:
    """Oracle: x10 and /10 by hand; an integer stays one and moves by one at least; the probe's
    relative size |moved - value| / |value|, SCALE for a zero."""
    assert gate._times(3.0, 10.0) == 30.0
    assert gate._times(3.0, 0.1) == pytest.approx(0.3)
    assert gate._times(3, 10.0) == 30
    assert gate._times(3, 0.1) == 0
    assert gate._times(1, 1.4) == 2  # round(1.4) = 1 is no move: one step up
    assert gate._times(1, 0.6) == 0  # round(0.6) = 1: one step down
    assert gate._times(0, 10.0) == 1
    assert gate._times(0, 0.1) == -1
    assert gate._times(25, 0.1) == 2
    assert gate.probe_size(2.0, 2.002) == pytest.approx(1e-3)
    assert gate.probe_size(-4.0, -3.0) == pytest.approx(0.25)
    assert gate.probe_size(0.0, 0.001) == gate.SCALE
    assert gate.probe_size(0, 1) == gate.SCALE


def test_settings() -> None:
    """Oracle: the module doc's numbers: a probe of 0.1 %, 10 %, a factor 10, a tenth of a
    tolerance; a group threshold a tenth of the flag linearised to a factor 10."""
    assert (gate.DELTA, gate.ZERO_STEP, gate.SCALE, gate.FACTOR) == (1e-3, 1e-3, 0.1, 10.0)
    assert gate.FLAG_TOLERANCES == 0.1
    assert gate.GROUP_TOLERANCES == pytest.approx(0.1 * 1e-3 / 9 / 10)
    assert (gate.STATEMENT_GROUP_REL, gate.STATEMENT_REPORT_REL, gate.EXACT_FLOOR_REL) == (1e-4, 1e-4, 1e-9)


# --- the gate's verdicts and report ------------------------------------------------------------


def _rec(**kw: Any) -> dict[str, Any]:
    """An effect record as Gate._perturb's ``record`` starts it, with some fields set."""
    base: dict[str, Any] = {
        "tolerances": 0.0,
        "tolerances_per_scale": 0.0,
        "flipped": False,
        "flipped_at_scale": False,
        "statement_numbers_rel": 0.0,
        "error": None,
        "error_at_scale": None,
        "tolerances_at_factor": 0.0,
        "flipped_at_factor": False,
        "error_at_factor": None,
        "inputs_changed_at_factor": [],
        "inputs_changed": [],
        "perturbed_to": [],
    }
    base.update(kw)
    return base


@pytest.mark.parametrize(
    ("rec", "flags", "moves"),
    [
        (_rec(), False, False),
        (_rec(tolerances_per_scale=0.1), False, False),  # at the threshold: not beyond it
        (_rec(tolerances_per_scale=0.11), True, True),
        (_rec(tolerances_per_scale=0.11, inputs_changed=["x"]), False, True),  # a declared input
        (_rec(tolerances_per_scale=0.11, error="E"), False, True),
        (_rec(flipped=True), True, True),
        (_rec(flipped=True, inputs_changed=["x"]), False, True),
        (_rec(flipped_at_scale=True), True, True),
        (_rec(flipped_at_scale=True, inputs_changed_at_scale=["x"]), False, True),
        (_rec(flipped_at_scale=True, inputs_changed=["x"]), True, True),
        (_rec(flipped_at_factor=True), True, True),
        (_rec(tolerances_at_factor=0.11), True, True),
        (_rec(tolerances_at_factor=0.1), False, False),
        (_rec(tolerances_at_factor=0.11, error_at_factor="E"), False, True),
        (_rec(tolerances_at_factor=0.11, inputs_changed_at_factor=["x"]), False, True),
        (_rec(flipped_at_factor=True, inputs_changed_at_factor=["x"]), False, True),
        (_rec(tolerances=5.0), False, False),  # the probe's raw effect is not the verdict
    ],
)
def test_flags_and_moves(rec: dict, flags: bool, moves: bool) -> None:
    """Oracle: the module doc's verdict: flagged when the probe (linearised to 10 %), a 10 %
    change or a factor 10 moves the claim past a tenth of its tolerance or flips it, with no
    recorded input changed and nothing raised (at that step)."""
    assert gate.Gate._flags("c", rec) is flags
    assert gate.Gate._moves(rec) is moves


def test_flags_and_moves_without_the_optional_keys() -> None:
    """Oracle: a record made before the factor step (no *_at_factor keys) is judged on the probe
    and the 10 % step alone."""
    rec = _rec(tolerances_per_scale=0.0)
    for k in ("tolerances_at_factor", "flipped_at_factor", "error_at_factor", "inputs_changed_at_factor"):
        del rec[k]
    assert gate.Gate._flags("c", rec) is False and gate.Gate._moves(rec) is False
    rec["tolerances_per_scale"] = 0.2
    assert gate.Gate._flags("c", rec) is True and gate.Gate._moves(rec) is True


def _finding(effects: dict[str, dict], **kw: Any) -> Any:
    return gate.Finding(_cand(**kw), effects=effects)


def _gate_with(tmp_path: Path, **kw: Any) -> Any:
    target = gate.Target(
        package="p", root=tmp_path / "p", claim_modules=list, repo=tmp_path, exposure_prefix="p.papers."
    )
    return gate.Gate(target, workdir=tmp_path / "work", log=lambda s: None, **kw)


def test_status(tmp_path: Path) -> None:
    """Oracle: the order of the verdicts: flagged (or, for an excused number, allowlisted or
    excused-by-rule), then breaks, declared, below-threshold, no-effect."""
    g = _gate_with(tmp_path)
    assert g._status(_finding({"a": _rec(flipped=True)})) == "flagged"
    assert (
        g._status(_finding({"a": _rec(flipped=True)}, allow={"reason": "r"}, rule="exponent"))
        == "allowlisted"
    )
    assert g._status(_finding({"a": _rec(flipped=True)}, rule="exponent")) == "excused-by-rule"
    assert g._status(_finding({"a": _rec(), "b": _rec(error="E")})) == "breaks"
    assert g._status(_finding({"a": _rec(error_at_scale="E")})) == "breaks"
    assert g._status(_finding({"a": _rec(flipped=True, inputs_changed=["x"])})) == "declared"
    assert (
        g._status(_finding({"a": _rec(flipped_at_scale=True, inputs_changed_at_scale=["x"])})) == "declared"
    )
    assert g._status(_finding({"a": _rec(inputs_changed=["x"], tolerances=1e-9)})) == "below-threshold"
    assert g._status(_finding({"a": _rec(tolerances=1e-9)})) == "below-threshold"
    assert g._status(_finding({"a": _rec(statement_numbers_rel=1e-9)})) == "below-threshold"
    assert g._status(_finding({"a": _rec()})) == "no-effect"
    assert g._status(_finding({})) == "no-effect"


def test_suggest_class() -> None:
    """Oracle: an allowlisted number keeps its entry's class (exact/unit by default); a unit's
    value or a number of a units module is exact/unit; a paper module's number a scenario value;
    else by where it is written."""
    t = gate.Target(package="p", root=Path("/x"), claim_modules=list)
    assert gate.suggest_class(_cand(allow={"reason": "r", "class": "exact"}), t) == "exact"
    assert gate.suggest_class(_cand(allow={"reason": "r"}), t) == "exact/unit"
    assert gate.suggest_class(_cand(value=-0.3048), t) == "exact/unit"
    assert gate.suggest_class(_cand(value=1852.0), t) == "exact/unit"
    assert gate.suggest_class(_cand(module="p.units", value=2.5), t) == "exact/unit"
    assert gate.suggest_class(_cand(module="p.papers.wf", value=2.5), t) == "scenario value"
    assert gate.suggest_class(_cand(module="p.papers", value=2.5), t) == "scenario value"
    assert gate.suggest_class(_cand(module="p.paperst", where="body", value=2.5), t) == (
        "rule of thumb / modelling constant"
    )
    assert gate.suggest_class(_cand(where="default", value=2.5), t) == "library default"
    assert gate.suggest_class(_cand(where="class", value=2.5), t) == "library default"
    assert gate.suggest_class(_cand(where="module", value=2.5), t) == "modelling constant"
    assert gate.suggest_class(_cand(where="body", value=2.5), t) == "rule of thumb / modelling constant"


def _reported_gate(tmp_path: Path) -> Any:
    """A gate whose phases are replaced by hand-made results: four candidates (one flagged on
    two papers' claims, one excused by rule, one allowlisted, one no claim runs), two findings."""
    g = _gate_with(tmp_path, papers=["WF"], seed=3, audit=True, max_seconds=60.0)
    g.meta = {
        "claims": {
            "WF-1": {"paper": "WF", "statement": False},
            "SP-1": {"paper": "SP", "statement": True},
            "SP-2": {"paper": "SP", "statement": False},
        }
    }
    flagged = _cand(
        id="p/papers/wf.py:3:4", module="p.papers.wf", file="p/papers/wf.py", lineno=3, text="2.5"
    )
    ruled = _cand(id="p/a.py:5:8", lineno=5, col=8, text="2", value=2, rule="exponent")
    allowed = _cand(id="p/a.py:6:4", lineno=6, text="0.3048", value=0.3048, allow={"reason": "exact foot"})
    idle = _cand(id="p/a.py:9:4", lineno=9, text="9.5", value=9.5, rule="index")
    below = _cand(id="p/a.py:7:4", lineno=7, text="7.5", value=7.5, where="default")
    g.all_candidates = [flagged, ruled, allowed, idle, below]
    g.rel = gate.Relevance(
        claims_of={
            flagged.id: {"WF-1", "SP-1"},
            ruled.id: {"WF-1"},
            allowed.id: {"SP-2"},
            idle.id: set(),
            below.id: {"WF-1"},
        },
        units_run={},
        used={},
    )
    g.tested = [flagged, below]
    g.findings = {
        flagged.id: gate.Finding(
            flagged,
            effects={
                "WF-1": _rec(tolerances_per_scale=2.5, tolerances=0.025),
                "SP-1": _rec(flipped_at_scale=True, statement_numbers_rel=0.5),
                "SP-2": _rec(),
            },
        ),
        below.id: gate.Finding(below, effects={"WF-1": _rec(tolerances=1e-6, tolerances_per_scale=0.01)}),
        idle.id: gate.Finding(idle, effects={}),
    }
    for f in g.findings.values():
        f.status = g._status(f)
    g.selected = ["WF-1", "SP-1", "SP-2"]
    g.traces = {"WF-1": {}, "SP-1": {"error": "boom"}, "SP-2": {}}
    g.unstable = {"SP-2": "moves by 1 tolerances"}
    g.children = 12
    g.trace_seconds = 1.26
    g.total_seconds = 10.04
    g.perturb_seconds = 3.35
    g.slow = ["WF-9"]
    return g


def test_report(tmp_path: Path) -> None:
    """Oracle: _reported_gate's hand-made findings, tallied by hand."""
    rep = _reported_gate(tmp_path).report()
    assert rep["selection"] == {
        "papers": ["WF"],
        "claims": [],
        "modules": [],
        "sample": None,
        "seed": 3,
        "audit": True,
        "max_seconds": 60.0,
        "left_out_as_slow": ["WF-9"],
    }
    assert rep["settings"]["delta"] == 1e-3 and rep["settings"]["factor"] == 10.0
    assert rep["settings"]["group_tolerances"] == gate.GROUP_TOLERANCES
    assert rep["settings"]["statement_report_rel"] == 1e-4
    n = rep["counts"]
    assert n == {
        "claims": 3,
        "claims_failing_nominally": ["SP-1"],
        "claims_order_dependent": {"SP-2": "moves by 1 tolerances"},
        "literals": 5,
        "literals_run_by_claims": 4,
        "excluded_by_rule": {"exponent": 1},
        "allowlisted": 1,
        "perturbed": 2,
        "flagged": 1,
        "by_status": {"below-threshold": 1, "flagged": 1},
        "per_paper": {"SP": {"numbers": 1, "claims": 1}, "WF": {"numbers": 1, "claims": 1}},
        "perturbed_evaluations": 12,
        "seconds": {"total": 10.0, "trace": 1.3, "perturb": 3.4},
    }
    assert rep["rules"] is gate.RULES
    first, second = rep["numbers"]
    assert first["status"] == "flagged" and second["status"] == "below-threshold"
    assert first["id"] == "p/papers/wf.py:3:4" and first["line"] == 3 and first["file"] == "p/papers/wf.py"
    assert first["flagged_claims"] == ["SP-1", "WF-1"]
    assert first["papers"] == ["SP", "WF"]
    assert first["flips"] == ["SP-1"]
    assert first["worst_tolerances"] == 2.5
    assert first["classification"] == "scenario value"
    assert first["text"] == "2.5" and first["source"] == "X = 0.5" and first["value"] == 0.5
    assert (first["scope"], first["module"], first["where"], first["binding"]) == (
        "<module>",
        "p.papers.wf",
        "module",
        "X",
    )
    assert first["rule"] == "" and first["allowlist_reason"] == ""
    assert sorted(first["effects"]) == ["SP-1", "WF-1"]  # SP-2 did not move
    assert first["effects"]["WF-1"]["paper"] == "WF" and first["effects"]["WF-1"]["statement"] is False
    assert first["effects"]["SP-1"]["statement"] is True
    assert first["effects"]["WF-1"]["tolerances_per_scale"] == 2.5
    assert second["flagged_claims"] == [] and second["worst_tolerances"] == 0.0
    assert second["effects"] == {}
    assert second["classification"] == "library default"


def test_report_effects_that_count(tmp_path: Path) -> None:
    """Oracle: an effect is reported when it moves the claim, raised, changed an input or moved a
    statement's numbers beyond STATEMENT_REPORT_REL; an infinite effect is written "inf"."""
    g = _reported_gate(tmp_path)
    c = g.all_candidates[4]
    g.findings = {
        c.id: gate.Finding(
            c,
            effects={
                "WF-1": _rec(tolerances_per_scale=math.inf, tolerances=math.inf),
                "SP-1": _rec(statement_numbers_rel=2e-4),
                "SP-2": _rec(inputs_changed=["x"]),
            },
        )
    }
    f = g.findings[c.id]
    f.status = g._status(f)
    (e,) = g.report()["numbers"]
    assert e["status"] == "flagged" and e["worst_tolerances"] == "inf"
    assert e["effects"]["WF-1"]["tolerances_per_scale"] == "inf"
    assert sorted(e["effects"]) == ["SP-1", "SP-2", "WF-1"]
    g.findings[c.id].effects = {"SP-1": _rec(statement_numbers_rel=1e-4), "WF-1": _rec(error="E")}
    f.status = g._status(f)
    (e,) = g.report()["numbers"]
    assert e["status"] == "breaks" and sorted(e["effects"]) == ["WF-1"]


def test_render_markdown(tmp_path: Path) -> None:
    """Oracle: the report of _reported_gate, written out by hand line by line where it matters."""
    rep = _reported_gate(tmp_path).report()
    md = gate.render_markdown(rep)
    lines = md.splitlines()
    assert lines[0] == "# Input gate: numbers that move claims without being declared inputs"
    assert "Selection: papers ['WF'], claims all, modules all, sample none (seed 3), audit." in lines
    assert "Left out as slower than 60 s: 1 claims (WF-9)." in lines
    assert "- claims: 3 (1 fail at their nominal inputs)" in lines
    assert "- claims whose value depends on what ran before them (not tested): 1" in lines
    assert "  - `SP-2`: moves by 1 tolerances" in lines
    assert "- numeric literals in scope: 5; run by the selected claims: 4" in lines
    assert "- excluded by rule: 1 (exponent 1)" in lines
    assert "- allowlisted (exact constants, unit definitions): 1" in lines
    assert "- perturbed: 2 in 12 perturbed evaluations" in lines
    assert "- by outcome: below-threshold 1, flagged 1" in lines
    assert "- **flagged: 1**" in lines
    assert "  - SP: 1 numbers moving 1 claims" in lines
    assert "- time: 10 s (trace 1 s, perturbation 3 s)" in lines
    assert any(
        x.startswith("A number is flagged when a change of it by 10 % (linearised from a probe of ±0.1 %)")
        for x in lines
    )
    assert "## SP" in lines and "## WF" in lines and lines.index("## SP") < lines.index("## WF")
    assert "### `p/papers/wf.py`" in lines
    assert "| line | number | in | bound to | moves (tolerances per 10 %) | suggested class |" in lines
    assert "| 3 | `2.5` | `<module>` | X | 1 claims: `SP-1` flips at ±10 % | scenario value |" in lines
    assert "| 3 | `2.5` | `<module>` | X | 1 claims: `WF-1` 2.5 | scenario value |" in lines
    assert "## Other outcomes" in lines
    # its one effect (0.01 per 10 %) moved nothing, so the report keeps none of its effects
    assert "| below-threshold | p/a.py:7 | `7.5` | `<module>` | worst 0 tolerances per 10 % |" in lines
    assert md.endswith("\n") and not md.endswith("\n\n\n")


def test_render_markdown_effect_wording_and_other_outcomes() -> None:
    """Oracle: each way a flagged effect is worded (flips, flips at 10 %, tolerances, flips at a
    factor, tolerances at a factor), the ninth claim and beyond summarised, and each other
    outcome's detail, written out by hand."""
    eff = {
        "A-flip": {**_rec(flipped=True, tolerances_per_scale=5.0), "paper": "A"},
        "A-scale": {**_rec(flipped_at_scale=True, tolerances_per_scale=4.0), "paper": "A"},
        "A-tol": {**_rec(tolerances_per_scale=0.55), "paper": "A"},
        "A-ffac": {
            **_rec(flipped_at_factor=True, tolerances_per_scale=0.1, tolerances_at_factor=50.0),
            "paper": "A",
        },
        "A-tfac": {**_rec(tolerances_at_factor="inf"), "paper": "A"},
    }
    for i in range(5):  # weights 0.110 to 0.114, below A-ffac's 0.1 + 1e-3 * 50
        eff[f"A-x{i}"] = {**_rec(tolerances_per_scale=0.11 + i / 1000), "paper": "A"}
    number = {
        "id": "f.py:1:0",
        "file": "f.py",
        "line": 1,
        "text": "2.5",
        "source": "y = a | b " + "x" * 100,
        "scope": "s",
        "binding": "",
        "status": "flagged",
        "classification": "c",
        "flagged_claims": sorted(eff),
        "papers": ["A"],
        "effects": eff,
    }

    def other(status: str, **kw: Any) -> dict:
        return {**number, "status": status, "line": 2, "effects": kw.pop("effects", {}), **kw}

    # exactly eight claims (no "and N more"); one effect from a run without the factor step
    old = _rec(tolerances_per_scale=0.05)
    del old["tolerances_at_factor"]
    eff8 = {"B-old": {**old, "paper": "A"}, "B-mid": {**_rec(tolerances_per_scale=0.0505), "paper": "A"}}
    for i in range(6):
        eff8[f"B-k{i}"] = {**_rec(tolerances_per_scale=1.5 + i), "paper": "A"}
    eight = {**number, "line": 3, "flagged_claims": sorted(eff8), "effects": eff8}
    eff9 = {**eff8, "B-z": {**_rec(), "paper": "A"}}  # a ninth, the lightest: counted, not shown
    nine = {**number, "line": 4, "flagged_claims": sorted(eff9), "effects": eff9}

    report = {
        "selection": {
            "papers": [],
            "claims": ["X"],
            "modules": ["m"],
            "sample": 4,
            "seed": 0,
            "audit": False,
        },
        "settings": {"scale": 0.1, "delta": 1e-3, "flag_tolerances": 0.1},
        "counts": {
            "claims": 1,
            "claims_failing_nominally": [],
            "claims_order_dependent": {},
            "literals": 1,
            "literals_run_by_claims": 1,
            "excluded_by_rule": {},
            "allowlisted": 0,
            "perturbed": 1,
            "perturbed_evaluations": 1,
            "by_status": {},
            "flagged": 1,
            "per_paper": {},
            "seconds": {"total": 0.4, "trace": 0.6, "perturb": 1.5},
        },
        "numbers": [
            number,
            eight,
            nine,
            other(
                "declared",
                effects={"c": _rec(inputs_changed=["b", "a", "e"]), "d": _rec(inputs_changed=["c", "d"])},
            ),
            other("breaks", effects={"c": _rec(error="Bad | thing " + "y" * 200), "d": _rec()}),
            other("breaks", effects={"c": _rec()}),
            other("allowlisted", allowlist_reason="exact", rule=""),
            other("excused-by-rule", allowlist_reason="", rule="index"),
            other(
                "below-threshold", effects={"c": _rec(tolerances_per_scale=0.05, statement_numbers_rel=3e-5)}
            ),
            other("below-threshold", effects={}),
        ],
    }
    lines = gate.render_markdown(report).splitlines()
    assert "Selection: papers all, claims ['X'], modules ['m'], sample 4 (seed 0)." in lines
    assert not [x for x in lines if x.startswith("Left out")]
    assert "- time: 0 s (trace 1 s, perturbation 2 s)" in lines
    assert "## Summary" in lines
    # no factor in the settings (an older run): a factor 10
    assert any("or by a factor 10 either way" in x and "else at ×/÷10." in x for x in lines)
    assert "- excluded by rule: 0 ()" in lines
    row = [x for x in lines if x.startswith("| 1 |")]
    # by weight (per 10 %, plus a thousandth of the factor's): the eight heaviest, then a count
    assert row == [
        "| 1 | `2.5` | `s` |  | 10 claims: `A-tfac` inf at ×/÷10, `A-flip` flips, `A-scale` flips at ±10 %, "
        "`A-tol` 0.55, `A-ffac` flips at ×/÷10, `A-x4` 0.114, `A-x3` 0.113, `A-x2` 0.112 and 2 more | c |"
    ]
    row8 = (
        "| 3 | `2.5` | `s` |  | 8 claims: `B-k5` 6.5, `B-k4` 5.5, `B-k3` 4.5, `B-k2` 3.5, `B-k1` 2.5, "
        "`B-k0` 1.5, `B-mid` 0 at ×/÷10, `B-old` 0 at ×/÷10 | c |"
    )
    assert lines[lines.index(row[0]) + 1] == row8
    assert lines[lines.index(row8) + 2 :][:2] == ["", "## Other outcomes"]  # after line 4's row
    assert lines[lines.index(row[0]) - 1] == "| --- | --- | --- | --- | --- | --- |"
    assert "| status | file:line | number | in | detail |" in lines
    assert (
        lines[lines.index("| status | file:line | number | in | detail |") + 1]
        == "| --- | --- | --- | --- | --- |"
    )
    assert not [x for x in lines if x.startswith("| flagged |")]  # flagged numbers are not "other"
    assert lines[-1] == "" and lines[-2].startswith("| below-threshold |")
    assert "| declared | f.py:2 | `2.5` | `s` | feeds `a`, `b`, `c`, `d` |" in lines
    assert [x for x in lines if x.startswith("| 4 |")] == [
        "| 4 | `2.5` | `s` |  | 9 claims: `B-k5` 6.5, `B-k4` 5.5, `B-k3` 4.5, `B-k2` 3.5, `B-k1` 2.5, "
        "`B-k0` 1.5, `B-mid` 0 at ×/÷10, `B-old` 0 at ×/÷10 and 1 more | c |"
    ]
    err = ("Bad | thing " + "y" * 200)[:120].replace("|", "\\|")
    assert f"| breaks | f.py:2 | `2.5` | `s` | {err} |" in lines
    assert "| breaks | f.py:2 | `2.5` | `s` |  |" in lines
    assert "| allowlisted | f.py:2 | `2.5` | `s` | exact |" in lines
    assert "| excused-by-rule | f.py:2 | `2.5` | `s` | index |" in lines
    assert (
        "| below-threshold | f.py:2 | `2.5` | `s` | worst 0.05 tolerances per 10 %; a statement's numbers "
        "3e-05 (relative) per probe |"
    ) in lines
    assert "| below-threshold | f.py:2 | `2.5` | `s` | worst 0 tolerances per 10 % |" in lines
    # a run made with another factor says so
    report["settings"]["factor"] = 4
    lines = gate.render_markdown(report).splitlines()
    assert any("or by a factor 4 either way" in x and "else at ×/÷4." in x for x in lines)
    assert "`A-tfac` inf at ×/÷4" in next(x for x in lines if x.startswith("| 1 |"))


# --- the whole gate in this process ------------------------------------------------------------


class _SyncScheduler:
    """A stand-in for the gate's Scheduler: runs each task in this process, in order, with the
    claims package forgotten first (as a fresh child would find it) and the callback called as
    the real one calls it."""

    made: ClassVar[list[tuple[Any, ...]]] = []

    def __init__(self, jobs: int, workdir: Path, nice: int = 0, log: Any = print) -> None:
        self.queue: list[Any] = []
        self.jobs = jobs
        self.log = log
        _SyncScheduler.made.append((jobs, workdir, nice, log))

    def submit(self, task: Any) -> None:
        self.queue.append(task)

    def run(self) -> None:
        import traceback

        while self.queue:
            task = self.queue.pop(0)
            _forget("gic")
            sys.meta_path[:] = [f for f in sys.meta_path if not isinstance(f, gate._PerturbedFinder)]
            try:
                result, error = task.fn(*task.args), None
            except Exception:
                result, error = None, traceback.format_exc()
            task.on_done(result, error)


@pytest.fixture
def sync_gate(gic: Any, monkeypatch: pytest.MonkeyPatch) -> Any:
    monkeypatch.setattr(gate, "Scheduler", _SyncScheduler)
    return gic


def test_gate_run_in_process(sync_gate: Any, tmp_path: Path) -> None:
    """Oracle: the claims package GIC by hand. drag's 0.47 moves WF-gic-drag (1.41 +- 0.005) by
    0.47 * 3 * 10 % = 0.141, 28.2 tolerances per 10 %; the statement horizon(100) > 35000 (35696)
    flips when R or the 100 m height drops by 10 % (33864 m) or its threshold rises by 10 %
    (38500), and when R is divided by 10; the failing claim is reported and never perturbed;
    the declared input's 3.0, the formula's 2.0 and 0.5 and the 0.0 are excluded by rule."""
    logs: list[str] = []
    _SyncScheduler.made = []
    g = gate.Gate(sync_gate, jobs=1, nice=3, workdir=tmp_path / "work", log=logs.append)
    rep = g.run()
    # the schedulers: reading the claims, the trace parent, its children, the control, the
    # perturbations (each at the gate's niceness but the trace parent, which only waits)
    work = tmp_path / "work"
    assert _SyncScheduler.made == [
        (1, work, 3, print),
        (1, work, 0, print),
        (1, work, 3, logs.append),
        (1, work, 3, print),
        (1, work, 3, logs.append),
    ]
    n = rep["counts"]
    assert n["claims"] == 3
    assert n["claims_failing_nominally"] == ["WF-gic-fails"]
    assert n["claims_order_dependent"] == {}
    assert n["excluded_by_rule"] == {
        "declared-input": 1,
        "exponent": 1,
        "formula-coefficient": 1,
        "identity": 1,
    }
    assert n["literals"] == 8 and n["literals_run_by_claims"] == 8
    assert n["perturbed"] == 4 and n["flagged"] == 4
    assert n["per_paper"] == {"WF": {"numbers": 4, "claims": 2}}
    by_text = {e["text"]: e for e in rep["numbers"]}
    assert set(by_text) == {"0.47", "6371000.0", "100.0", "35000.0"}
    drag = by_text["0.47"]
    assert drag["flagged_claims"] == ["WF-gic-drag"] and drag["flips"] == []
    assert drag["worst_tolerances"] == pytest.approx(28.2, rel=1e-6)
    assert drag["effects"]["WF-gic-drag"]["tolerances"] == pytest.approx(0.282, rel=1e-6)
    radius = by_text["6371000.0"]["effects"]["WF-gic-statement"]
    assert radius["statement_numbers_rel"] == pytest.approx(0.5e-3, rel=0.01)
    assert not radius["flipped"] and radius["flipped_at_scale"] and radius["flipped_at_factor"]
    assert radius["tolerances_at_factor"] == 0.0
    assert by_text["6371000.0"]["flips"] == ["WF-gic-statement"]
    height = by_text["100.0"]["effects"]["WF-gic-statement"]
    assert height["flipped_at_scale"] and not height["flipped"]
    threshold = by_text["35000.0"]["effects"]["WF-gic-statement"]
    assert threshold["flipped_at_scale"] and threshold["statement_numbers_rel"] == 0.0
    assert n["perturbed_evaluations"] == g.children > 0
    # the probes of the two modules' groups (model: drag and the statement, both moved; claims:
    # the statement, moved by the height), each then split into single literals
    assert g.group_log == [
        {"size": 2, "claims": 2, "moved": 2, "depth": 0, "error": False},
        {"size": 2, "claims": 1, "moved": 1, "depth": 0, "error": False},
    ]
    # 0.47: one probe (+0.1 %), flagged at once; R: both probes (it moved without flagging),
    # +-10 % on the statement, then x10 and /10
    assert drag["effects"]["WF-gic-drag"]["perturbed_to"] == [0.47 * (1 + 1e-3)]
    r = 6371000.0
    assert sorted(radius["perturbed_to"]) == sorted(
        [r * (1 + 1e-3), r * (1 - 1e-3), r * 1.1, r * 0.9, r * 10.0, r / 10.0]
    )
    assert threshold["perturbed_to"][0] == 35000.0 * (1 + 1e-3)
    assert any(s.startswith("reading the claims") for s in logs)
    assert any(s.startswith("tracing 3 claims") for s in logs)
    assert "perturbing 4 literals in 2 modules" in logs
    assert "trying the paper modules' literals at +-10 % on the statements" in logs
    # a second run reuses the stored trace: no claims read, nothing traced
    logs.clear()
    again = gate.Gate(sync_gate, jobs=1, nice=0, workdir=tmp_path / "work", log=logs.append).run()
    assert not [s for s in logs if s.startswith(("reading the claims", "tracing"))]
    assert again["counts"]["flagged"] == 4
    assert again["counts"]["seconds"]["trace"] == 0.0


ORDER_DEPENDENT = """
CLAIMS += [
    _c("WF-gic-b1", "1.0", lambda: _bump()),
    _c("WF-gic-b2", "1.0", lambda: _bump()),
    Claim(id="WF-gic-b3", paper="WF", locator="Table 1", quantity="s", published=True, unit="statement",
          compute=lambda: _bump() > 2.5, tolerance=EXACT, expected_status="reproduced", note="synthetic"),
    _c("WF-gic-b4", "1.0", lambda: _strict()),
    _c("WF-gic-b5", "1.0", lambda: 1.0 + 0.001 * _bump()),
    Claim(id="WF-gic-b6", paper="WF", locator="Table 1", quantity="s", published=True, unit="statement",
          compute=lambda: _bump() > 0.5, tolerance=EXACT, expected_status="reproduced", note="synthetic"),
]
_N = [0]


def _bump():
    _N[0] += 1
    return float(_N[0])


def _strict():
    if _bump() > 3.5:
        raise ValueError("ran after others")
    return 1.0
"""


def test_gate_control_finds_order_dependent_claims(sync_gate: Any, tmp_path: Path) -> None:
    """Oracle: claims that count their own evaluations (a module-level counter), by hand: alone
    each sees 1; in the control's one process, in order, b1 sees 1 (stable), b2 2 (1 tolerance is
    0.05: 20 tolerances), the statement b3 3 > 2.5 (flips; its number moves 2/3), b4 4 (raises),
    b5 1.005 against 1.001 (0.08 tolerances), the statement b6 6 > 0.5 (no flip; 5/6)."""
    claims = tmp_path / "gic" / "claims.py"
    claims.write_text(claims.read_text() + ORDER_DEPENDENT)
    g = gate.Gate(sync_gate, workdir=tmp_path / "work", log=lambda s: None)
    g._prepare()
    g._trace()
    assert g.traces["WF-gic-b2"]["value"] == 1.0 and g.traces["WF-gic-b4"]["value"] == 1.0
    g._control()
    assert g.unstable == {
        "WF-gic-b2": "moves by 20 tolerances; inputs []",
        "WF-gic-b3": "flipped: True; its numbers move by 0.667 (relative)",
        "WF-gic-b4": "ValueError: ran after others",
        "WF-gic-b5": "moves by 0.08 tolerances; inputs []",
        "WF-gic-b6": "flipped: False; its numbers move by 0.833 (relative)",
    }


def test_gate_selection(sync_gate: Any, tmp_path: Path) -> None:
    """Oracle: the three claims of GIC: one paper's claims, a claim prefix, a seeded sample (in
    registry order), the numbers of one module only, and a time limit that leaves every claim
    out (all take longer than 0 s)."""
    work = tmp_path / "work"
    g = gate.Gate(sync_gate, papers=["SP"], workdir=work, log=lambda s: None)
    g._prepare()
    assert g.selected == []
    g = gate.Gate(sync_gate, claim_prefixes=["WF-gic-s", "WF-gic-f"], workdir=work, log=lambda s: None)
    g._prepare()
    assert g.selected == ["WF-gic-statement", "WF-gic-fails"]
    g = gate.Gate(sync_gate, sample=2, seed=5, workdir=work, log=lambda s: None)
    g._prepare()
    import random

    all_ids = ["WF-gic-drag", "WF-gic-statement", "WF-gic-fails"]
    expected = sorted(random.Random(5).sample(all_ids, 2), key=all_ids.index)
    assert g.selected == expected
    g = gate.Gate(sync_gate, sample=3, workdir=work, log=lambda s: None)
    g._prepare()
    assert g.selected == all_ids
    g = gate.Gate(sync_gate, modules=["claims"], workdir=work, log=lambda s: None, max_seconds=0.0)
    g._prepare()
    g._trace()
    assert g.slow == all_ids and g.selected == [] and g.traces == {}
    g._candidates()
    assert {c.module for c in g.all_candidates} == {"gic.claims"}
    assert g.tested == []
    assert g._modules(["WF-gic-drag"]) == ["gic.claims"]


def test_gate_prepare_clears_old_task_files_and_ignores_a_bad_cache(sync_gate: Any, tmp_path: Path) -> None:
    """Oracle: a task file left by a killed run is removed; an unreadable cache is read afresh;
    without the cache nothing is written."""
    work = tmp_path / "work"
    work.mkdir()
    (work / "task-1-1.pkl").write_text("x")
    g = gate.Gate(sync_gate, workdir=work, log=lambda s: None)
    key = gate._source_key(sync_gate)
    (work / f"trace-gic-{key}.json").write_text("{not json")
    g._prepare()
    assert not (work / "task-1-1.pkl").exists()
    assert g.cache_file == work / f"trace-gic-{key}.json"
    assert set(g.meta) == {"claims", "third_party"} and len(g.selected) == 3
    nocache = gate.Gate(sync_gate, workdir=tmp_path / "w2", use_cache=False, log=lambda s: None)
    nocache._prepare()
    nocache._trace()
    assert not list((tmp_path / "w2").glob("trace-*"))
    assert set(nocache.traces) == {"WF-gic-drag", "WF-gic-statement", "WF-gic-fails"}


def test_gate_preload_refuses_an_imported_navcore(tmp_path: Path) -> None:
    """Oracle: this test process has imported navcore, which the perturbation parent must not;
    another package already imported is only skipped; third-party modules are imported."""
    import navcore  # noqa: F401

    t = gate.Target(package="navcore", root=tmp_path, claim_modules=list)
    g = gate.Gate(t, workdir=tmp_path, log=lambda s: None)
    g.meta = {"third_party": []}
    with pytest.raises(RuntimeError, match="must not import navcore"):
        g._preload()
    other = gate.Gate(gate.Target(package="json", root=tmp_path, claim_modules=list), workdir=tmp_path)
    other.meta = {"third_party": ["json", "no_such_module_xyz", "colorsys"]}
    sys.modules.pop("colorsys", None)
    other._preload()
    assert "colorsys" in sys.modules and "no_such_module_xyz" not in sys.modules


def test_progress_logs_every_fiftieth_evaluation(tmp_path: Path) -> None:
    """Oracle: a line at 50 and 100 evaluations, none at 49."""
    logs: list[str] = []
    g = _gate_with(tmp_path)
    g.log = logs.append
    g.sched = _SyncScheduler(1, tmp_path)
    g.sched.queue = [1, 2]
    for n in (49, 50, 100):
        g.children = n
        g._progress(time.monotonic())
    assert [s.split(" (")[0] for s in logs] == [
        "  50 perturbed evaluations, 2 queued",
        "  100 perturbed evaluations, 2 queued",
    ]


# --- cache key, scheduler, merging, the command line -------------------------------------------


def test_source_key(tmp_path: Path) -> None:
    """Oracle: 20 hex digits that change with a file's content and with its name, not with a
    non-Python file."""
    _write_pkg(tmp_path / "k", {"a.py": "A = 1\n", "notes.txt": "x"})
    t = gate.Target(package="k", root=tmp_path / "k", claim_modules=list)
    k1 = gate._source_key(t)
    assert len(k1) == 20 and int(k1, 16) >= 0
    assert gate._source_key(t) == k1
    (tmp_path / "k" / "notes.txt").write_text("y")
    assert gate._source_key(t) == k1
    (tmp_path / "k" / "a.py").write_text("A = 2\n")
    k2 = gate._source_key(t)
    assert k2 != k1
    (tmp_path / "k" / "a.py").rename(tmp_path / "k" / "b.py")
    assert gate._source_key(t) not in (k1, k2)


def _twice(x: int) -> int:
    return 2 * x


def _fail() -> None:
    raise ValueError("no good")


def _die() -> None:
    import os

    os.write(1, b"last words\n")
    os._exit(3)


def test_scheduler_runs_tasks_in_children(tmp_path: Path) -> None:
    """Oracle: 2 * 21 = 42 from a child; a raising child's traceback; a child that exits without
    a result, with its output; a child that outlives its timeout; task files cleaned up (the
    failed task's log is kept)."""
    got: dict[str, Any] = {}

    def cb(key: str) -> Any:
        return lambda result, error: got.__setitem__(key, (result, error))

    s = gate.Scheduler(2, tmp_path)
    s.submit(gate.Task("ok", _twice, (21,), 30.0, cb("ok")))
    s.submit(gate.Task("fail", _fail, (), 30.0, cb("fail")))
    s.submit(gate.Task("die", _die, (), 30.0, cb("die")))
    s.submit(gate.Task("slow", time.sleep, (30,), 0.3, cb("slow")))
    s.run()
    assert got["ok"] == (42, None)
    assert got["fail"][0] is None and "ValueError: no good" in got["fail"][1]
    assert got["die"][0] is None and got["die"][1].startswith("the child died without a result: ")
    assert "last words" in got["die"][1]
    assert got["slow"] == (None, "timed out after 0 s")
    assert s.done == 4 and s.n == 4 and s.running == {}
    assert not list(tmp_path.glob("*.pkl")) and not list(tmp_path.glob("*.tmp"))
    assert len(list(tmp_path.glob("*.log"))) == 3  # the failed, dead and timed-out tasks' logs


def test_run_in_child(tmp_path: Path) -> None:
    """Oracle: 2 * 4 = 8 through a child; a failing child raises with its traceback."""
    assert gate._run_in_child(_twice, (4,), tmp_path, 0) == 8
    with pytest.raises(RuntimeError, match=r"(?s)a child failed:.*no good"):
        gate._run_in_child(_fail, (), tmp_path, 0)


def test_merge_reports(tmp_path: Path) -> None:
    """Oracle: two runs by hand: a number found by both keeps both runs' effects, the union of
    flagged claims, flips and papers, the worst effect and the strongest status; the counts add
    up (the literal count is the first run's)."""
    rep = _reported_gate(tmp_path).report()
    second = json.loads(json.dumps(rep))
    second["selection"]["papers"] = ["SP"]
    second["selection"]["audit"] = False
    n0 = second["numbers"][0]
    n0["effects"] = {"KZL-9": {**_rec(flipped=True), "paper": "KZL", "statement": True}}
    n0["flagged_claims"] = ["KZL-9"]
    n0["flips"] = ["KZL-9"]
    n0["papers"] = ["KZL"]
    n0["worst_tolerances"] = "inf"
    n1 = second["numbers"][1]
    n1["status"] = "breaks"
    z = json.loads(json.dumps(rep["numbers"][0]))
    z.update(id="z", flagged_claims=["WF-2"], flips=[], papers=["WF"], effects={"WF-2": {"paper": "WF"}})
    second["numbers"].append(z)
    second["counts"]["excluded_by_rule"] = {"seed": 1, "exponent": 2, "index": 1}
    second["counts"]["claims_order_dependent"] = {"SP-3": "why"}
    merged = gate.merge_reports([rep, second])
    a, z_merged, b = merged["numbers"]
    assert z_merged["id"] == "z"
    assert a["flagged_claims"] == ["KZL-9", "SP-1", "WF-1"]
    assert a["flips"] == ["KZL-9", "SP-1"]
    assert a["papers"] == ["KZL", "SP", "WF"]
    assert a["worst_tolerances"] == math.inf
    assert sorted(a["effects"]) == ["KZL-9", "SP-1", "WF-1"]
    assert b["status"] == "breaks"  # breaks outranks below-threshold
    # the inputs are not changed
    assert rep["numbers"][0]["flagged_claims"] == ["SP-1", "WF-1"]
    assert sorted(rep["numbers"][0]["effects"]) == ["SP-1", "WF-1"]
    # one run alone: every number of it, as it is
    alone = gate.merge_reports([rep])
    assert [e["id"] for e in alone["numbers"]] == [e["id"] for e in rep["numbers"]]
    assert alone["numbers"][1] == rep["numbers"][1]
    n = merged["counts"]
    assert n["claims"] == 6 and n["perturbed"] == 4 and n["perturbed_evaluations"] == 24
    assert n["allowlisted"] == 2 and n["literals_run_by_claims"] == 8 and n["literals"] == 5
    assert n["claims_failing_nominally"] == ["SP-1", "SP-1"]
    assert n["claims_order_dependent"] == {"SP-2": "moves by 1 tolerances", "SP-3": "why"}
    assert n["excluded_by_rule"] == {"exponent": 3, "index": 1, "seed": 1}
    assert (
        list(n["excluded_by_rule"]) == ["exponent", "index", "seed"] and type(n["excluded_by_rule"]) is dict
    )
    assert n["seconds"] == {"total": 20.0, "trace": 2.6, "perturb": 6.8}
    assert n["flagged"] == 2 and n["by_status"] == {"breaks": 1, "flagged": 2}
    assert n["per_paper"] == {
        "KZL": {"numbers": 1, "claims": 1},
        "SP": {"numbers": 1, "claims": 1},
        "WF": {"numbers": 2, "claims": 2},
    }
    sel = merged["selection"]
    assert sel == {
        "papers": ["SP", "WF"],
        "claims": [],
        "modules": [],
        "sample": None,
        "seed": 0,
        "audit": True,
        "merged_runs": 2,
    }
    assert merged["settings"] == rep["settings"]
    assert merged["rules"] == rep["rules"] and merged["excluded_modules"] == rep["excluded_modules"]
    # the weaker status of a later run does not replace a stronger one
    third = json.loads(json.dumps(rep))
    third["numbers"][0]["status"] = "declared"
    assert gate.merge_reports([rep, third])["numbers"][0]["status"] == "flagged"
    assert gate.merge_reports([third, rep])["numbers"][0]["status"] == "flagged"
    empty = gate.merge_reports([])
    assert empty["numbers"] == [] and empty["counts"]["literals"] == 0 and empty["rules"] is gate.RULES


def test_reapply_rules(tmp_path: Path) -> None:
    """Oracle: a stored report whose flagged number is now allowlisted, another now excused by a
    rule, a third still flagged, and a below-threshold number left alone; the counts follow."""

    def entry(i: str, paper: str, status: str = "flagged") -> dict:
        return {
            "id": i,
            "status": status,
            "papers": [paper],
            "flagged_claims": [f"{paper}-1"],
            "effects": {f"{paper}-1": {"paper": paper}},
            "rule": "",
            "allowlist_reason": "",
        }

    two = entry("e", "ATC")
    two["flagged_claims"] = ["ATC-1", "ATC-2"]
    two["effects"]["ATC-2"] = {"paper": "ATC"}
    report = {
        "numbers": [
            entry("gone", "ATC"),  # not a candidate any more: left as it is
            entry("d", "KZL", "below-threshold"),  # not flagged: left alone
            entry("a", "WF"),
            entry("b", "SP"),
            entry("c", "SP"),
            two,
        ],
        "counts": {"flagged": 6, "by_status": {}, "per_paper": {}},
    }
    index = gate.Index(target=gate.Target(package="p", root=tmp_path, claim_modules=list))
    index.candidates = [
        _cand(id="a", allow={"reason": "exact"}),
        _cand(id="b", rule="exponent"),
        _cand(id="c"),
        _cand(id="d", rule="index"),
        _cand(id="e"),
    ]
    gate.reapply_rules(report, index)
    st = {e["id"]: e["status"] for e in report["numbers"]}
    assert st == {
        "a": "allowlisted",
        "b": "excused-by-rule",
        "c": "flagged",
        "d": "below-threshold",
        "e": "flagged",
        "gone": "flagged",
    }
    assert report["numbers"][2]["allowlist_reason"] == "exact" and report["numbers"][2]["rule"] == ""
    assert report["numbers"][3]["rule"] == "exponent" and report["numbers"][3]["allowlist_reason"] == ""
    assert report["counts"]["flagged"] == 3
    assert report["counts"]["by_status"] == {
        "allowlisted": 1,
        "below-threshold": 1,
        "excused-by-rule": 1,
        "flagged": 3,
    }
    # ATC: two flagged numbers ("gone" and "e") moving ATC-1 and ATC-2
    assert report["counts"]["per_paper"] == {
        "ATC": {"numbers": 2, "claims": 2},
        "SP": {"numbers": 1, "claims": 1},
    }


def test_main_merge(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Oracle: two stored runs with one flagged number that no candidate of the (stand-in,
    empty) package excuses: merged, written, exit status 1; with none flagged, 0."""
    (tmp_path / "empty").mkdir()
    monkeypatch.setattr(
        gate,
        "navcore_target",
        lambda: gate.Target(package="empty", root=tmp_path / "empty", claim_modules=list),
    )
    rep = _reported_gate(tmp_path).report()
    rep["numbers"] = rep["numbers"][:1]
    rep["numbers"][0]["id"] = "not/a/candidate.py:1:1"
    runs = []
    for i in (1, 2):
        p = tmp_path / f"run{i}.json"
        p.write_text(json.dumps(rep))
        runs.append(str(p))
    out = tmp_path / "deep" / "out"
    assert gate.main(["--merge", *runs, "--out", str(out)]) == 1
    text = (out / "input_gate.json").read_text()
    assert text.startswith('{\n "selection": {\n  "papers"') and text.endswith("}\n")  # indented by one
    merged = json.loads(text)
    assert merged["counts"]["flagged"] == 1 and merged["selection"]["merged_runs"] == 2
    assert (out / "input_gate.md").read_text().startswith("# Input gate")
    assert capsys.readouterr().out.strip() == "input gate: 1 flagged numbers in 2 runs"
    rep["numbers"] = []
    (tmp_path / "run1.json").write_text(json.dumps(rep))
    assert gate.main(["--merge", runs[0], "--out", str(out)]) == 0


def test_lambda_inside_a_lambda(tmp_path: Path) -> None:
    """Oracle: ``lambda x: (lambda y: 2.5 * y)(x)`` on line 1 makes two functions, the inner one
    named after the outer; 2.5 is in the inner one's body."""
    _write_pkg(tmp_path / "n", {"__init__.py": "", "a.py": "NEST = lambda x: (lambda y: 2.5 * y)(x)\n"})
    index = gate.index_package(
        gate.Target(package="n", root=tmp_path / "n", claim_modules=list, repo=tmp_path)
    )
    assert [(f.qualname, f.top) for f in index.functions] == [
        ("<module>.<lambda:1>", None),
        ("<module>.<lambda:1>.<lambda:1>", None),
    ]
    (c,) = index.candidates
    assert (c.scope, c.where, c.unit) == (
        "<module>.<lambda:1>.<lambda:1>",
        "body",
        index.functions[1].units[0],
    )


def test_lambda_inside_a_lambda_in_a_def(tmp_path: Path) -> None:
    """Oracle: inside ``def g``, both lambdas (one inside the other) belong to g's top-level name."""
    _write_pkg(tmp_path / "n", {"b.py": "def g():\n    return (lambda x: (lambda y: y)(x))(1)\n"})
    index = gate.index_package(
        gate.Target(package="n", root=tmp_path / "n", claim_modules=list, repo=tmp_path)
    )
    tops = {f.qualname: f.top for f in index.functions}
    assert tops == {"g": ("n.b", "g"), "g.<lambda:2>": ("n.b", "g"), "g.<lambda:2>.<lambda:2>": ("n.b", "g")}


def test_navcore_target() -> None:
    """Oracle: the module doc: navcore's library and paper modules, its excluded modules, the
    paper modules' functions exposed to statements, the committed allowlist."""
    from navcore.ledger.registry import paper_modules

    t = gate.navcore_target()
    assert t.package == "navcore" and t.root == gate.ROOT / "navcore" and t.repo == gate.ROOT
    assert t.exclude is gate.EXCLUDED_MODULES and t.exposure_prefix == "navcore.papers."
    assert t.allowlist == gate.ALLOWLIST == gate.ROOT / "tools" / "input_gate_allowlist.toml"
    assert t.claim_modules() == list(paper_modules())
    assert "ledger" in gate.EXCLUDED_MODULES and "_validate" in gate.EXCLUDED_MODULES


def test_exit_on_signal() -> None:
    """Oracle: SIGTERM (15) exits with 128 + 15, as a shell reports it."""
    with pytest.raises(SystemExit) as exc:
        gate._exit_on_signal(15, None)
    assert exc.value.code == 143


HELPS = [
    "The input gate: find every number that moves a ledger claim without being a declared input.",
    "only this paper's claims (repeatable)",
    "only claims whose id starts with this",
    "only numbers in modules matching this",
    "N claims drawn at random (seeded)",
    "niceness of the children (default 5)",
    "also perturb excluded and allowlisted numbers",
    "leave out claims whose nominal evaluation takes longer (a quick sample)",
    "trace again even if a trace is stored",
    "folder of input_gate.json/.md",
    "the trace cache and the children's files",
    "combine the input_gate.json of several runs (one per paper) into --out; runs nothing",
]


def test_main_help(capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    """Oracle: the module doc's first paragraph and each option's help, as written in main."""
    monkeypatch.setenv("COLUMNS", "400")
    with pytest.raises(SystemExit):
        gate.main(["--help"])
    out = " ".join(capsys.readouterr().out.split())
    for text in HELPS:
        assert re.search(rf"(?<!\S){re.escape(text)}(?!\S)", out), text
    assert "LEDGER.md" not in out  # only the doc's first paragraph
    for opt in (
        "--paper",
        "--claim",
        "--module",
        "--sample",
        "--seed",
        "--jobs",
        "--nice",
        "--audit",
        "--max-seconds",
        "--no-cache",
        "--out",
        "--workdir",
        "--merge",
    ):
        assert f"[{opt}" in out


class _FakeGate:
    made: ClassVar[list[tuple[Any, dict]]] = []
    report: ClassVar[dict] = {}

    def __init__(self, target: Any, **kw: Any) -> None:
        _FakeGate.made.append((target, kw))

    def run(self) -> dict:
        return _FakeGate.report


@pytest.fixture
def fake_main(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Any:
    """main() with a stand-in Gate (it records its arguments and returns a hand-made report),
    signal handlers recorded rather than installed, and the environment restored afterwards."""
    _FakeGate.made = []
    _FakeGate.report = _reported_gate(tmp_path).report()
    monkeypatch.setattr(gate, "Gate", _FakeGate)
    target = gate.Target(package="t", root=tmp_path, claim_modules=list)
    monkeypatch.setattr(gate, "navcore_target", lambda: target)
    handlers: list[tuple[Any, Any]] = []
    monkeypatch.setattr(gate.signal, "signal", lambda sig, h: handlers.append((sig, h)))
    for var in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "MPLBACKEND", "NAVCORE_NO_DISK_CACHE"):
        monkeypatch.delenv(var, raising=False)
    monkeypatch.delenv("OMP_NUM_THREADS", raising=False)
    monkeypatch.setenv("MKL_NUM_THREADS", "4")
    monkeypatch.setenv("NAVCORE_CACHE", "on")
    return target, handlers


def test_main_runs_the_gate_with_its_defaults(
    fake_main: Any, tmp_path: Path, capsys: pytest.CaptureFixture
) -> None:
    """Oracle: main's argument defaults (two jobs at niceness 5, the trace cache on, the work
    folder under _build), the environment a run needs (one BLAS thread unless set, no caches,
    Agg), the handlers that stop it cleanly, the two files written and exit status 1 for a
    flagged number."""
    import os
    import signal

    target, handlers = fake_main
    out = tmp_path / "out"
    assert gate.main(["--out", str(out)]) == 1
    ((got_target, kw),) = _FakeGate.made
    assert got_target is target
    log = kw.pop("log")
    assert kw == {
        "papers": [],
        "claim_prefixes": [],
        "modules": [],
        "sample": None,
        "seed": 0,
        "jobs": 2,
        "nice": 5,
        "audit": False,
        "workdir": gate.ROOT / "_build" / "input_gate",
        "use_cache": True,
        "max_seconds": None,
    }
    log("a line from the gate")
    assert handlers == [(signal.SIGINT, signal.default_int_handler), (signal.SIGTERM, gate._exit_on_signal)]
    assert os.environ["OPENBLAS_NUM_THREADS"] == "1" and os.environ["OMP_NUM_THREADS"] == "1"
    assert os.environ["MKL_NUM_THREADS"] == "4"  # set before: kept
    assert os.environ["NAVCORE_CACHE"] == "off" and os.environ["NAVCORE_NO_DISK_CACHE"] == "1"
    assert os.environ["MPLBACKEND"] == "Agg"
    written = (out / "input_gate.json").read_text()
    assert json.loads(written) == json.loads(json.dumps(_FakeGate.report))
    # indented by one space, in the report's own order (selection first, not sorted)
    assert written.endswith("}\n") and written.startswith('{\n "selection": {')
    assert (out / "input_gate.md").read_text() == gate.render_markdown(_FakeGate.report)
    printed = capsys.readouterr().out.splitlines()
    assert printed == [
        f"input gate: 1 flagged numbers; 2 perturbed; report in {out / 'input_gate.md'}",
        "a line from the gate",  # the gate's log prints
    ]


def test_main_writes_under_build_by_default(
    fake_main: Any, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Oracle: without --out the report goes to <repository>/_build (here a stand-in root), made
    if missing, and again when it exists."""
    monkeypatch.setattr(gate, "ROOT", tmp_path / "repo")
    assert gate.main([]) == 1
    assert (tmp_path / "repo" / "_build" / "input_gate.json").exists()
    assert gate.main([]) == 1
    assert _FakeGate.made[0][1]["workdir"] == tmp_path / "repo" / "_build" / "input_gate"


def test_main_passes_every_option(fake_main: Any, tmp_path: Path) -> None:
    """Oracle: each option given once (and --paper twice) arrives at the gate as written; no
    flagged number means exit status 0."""
    _FakeGate.report["counts"]["flagged"] = 0
    out = tmp_path / "deep" / "out"
    argv = [
        "--paper",
        "WF",
        "--paper",
        "SP",
        "--claim",
        "WF-1",
        "--module",
        "antenna",
        "--sample",
        "3",
        "--seed",
        "7",
        "--jobs",
        "1",
        "--nice",
        "2",
        "--audit",
        "--max-seconds",
        "2.5",
        "--no-cache",
        "--out",
        str(out),
        "--workdir",
        str(tmp_path / "w"),
    ]
    assert gate.main(argv) == 0
    ((_, kw),) = _FakeGate.made
    kw.pop("log")
    assert kw == {
        "papers": ["WF", "SP"],
        "claim_prefixes": ["WF-1"],
        "modules": ["antenna"],
        "sample": 3,
        "seed": 7,
        "jobs": 1,
        "nice": 2,
        "audit": True,
        "workdir": tmp_path / "w",
        "use_cache": False,
        "max_seconds": 2.5,
    }
    assert (out / "input_gate.json").exists()
