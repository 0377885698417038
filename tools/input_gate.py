"""The input gate: find every number that moves a ledger claim without being a declared input.

LEDGER.md: every number that can move a verdict (a modelling constant, a scenario value, a
rule of thumb, a library default a claim relies on) is a declared input with its provenance;
only unit definitions and exact constants stay plain. This tool checks that by experiment::

    python tools/input_gate.py                      # every claim (long: see below)
    python tools/input_gate.py --paper WF           # one paper's claims
    python tools/input_gate.py --claim ATC10-tab4.2 # claims whose id starts with this
    python tools/input_gate.py --module antenna     # only the numbers of matching modules
    python tools/input_gate.py --sample 20 --seed 1 # 20 claims drawn at random (seeded)

(``nox -s inputs -- ARGS``). It writes ``_build/input_gate.json`` and ``_build/input_gate.md``
and exits 1 if it flags a number that the allowlist does not excuse.

How it works
------------
1. **Candidates** (static, :func:`index_package`): every numeric literal of the library and
   paper modules (``ast.Constant`` int/float, with its sign when written ``-x``): in a
   function body, in a function's or lambda's keyword default, in a class body (a dataclass
   field default), or at module level (a module constant, a scenario table). Literals that a
   committed rule excludes (:data:`RULES`: indices and shapes, exponents of squares and roots,
   0 and 1 as identities, formula coefficients, decibel factors, unit conversions, seeds,
   error messages, declared inputs and claim metadata) are not perturbed; the allowlist
   (``tools/input_gate_allowlist.toml``: unit definitions and exact constants, each with its
   reason) names the rest that may stay plain.
2. **Trace** (per claim, from cold caches): a process imports the package without evaluating
   anything; for each claim it forks a child that evaluates the claim once at its nominal
   inputs under ``coverage`` (lines executed) and records its value, the inputs it read (the
   ledger's own recording) and, for a statement, the numbers the paper module's functions
   return on the way (what the statement compares).
3. **Relevance**: a literal in a function body is relevant to the claims that executed its
   statement; a default to the claims that executed its function; a class-body or
   module-level literal to the claims that use its name (a name on an executed line, resolved
   through ``import`` and ``from m import X``, and everything a used name was built from at
   import time, transitively).
4. **Perturbation**: every literal of a module is changed at once (relative 1e-3, distinct
   pseudo-random signs and magnitudes; integers by a whole step; 0 by ±1e-3) by rewriting the
   module's syntax tree as it is imported, in a fresh child forked from a process that has
   imported the third-party libraries but not the package: every cache starts cold (the
   ledger's ``input_cache`` memos, ``functools.cache``, the on-disk caches are off), and
   import-time uses (``from m import X``, dataclass defaults, instances built at import)
   see the perturbed value. Only the claims the group is relevant to are evaluated, quickest
   first, stopping at the first that moves. A group whose probe moves a claim by more than a
   tenth of what could reach the flag at a factor 10 (a statement: its numbers move by more
   than 1e-4 relative) is split in two, recursively, down to single literals, which are
   evaluated at +1e-3 (and -1e-3 where that did not flag), then at x10 and /10 where the probe
   says that could matter. The paper modules' literals are also tried at +-10 % on the
   statements (a statement's own threshold moves none of its numbers).
5. **Verdict**: a literal is flagged when a 10 % change of it (linearised from the probe), or
   a factor 10 either way (evaluated, where the probe says it could matter), moves a numeric
   claim by more than a tenth of its tolerance (``resolve_tolerance(claim).allowed(published)``),
   or when the probe, a 10 % change or a factor 10 flips a statement, while none of the inputs
   the claim recorded changed (a literal that feeds a declared input's value is declared).

Two cores by default (``--jobs``); every child runs under ``nice``. The trace is kept in
``_build/input_gate/`` keyed by a hash of the package's sources, so a run per paper reuses it.
"""

from __future__ import annotations

import argparse
import ast
import bisect
import contextlib
import hashlib
import importlib
import importlib.abc
import importlib.machinery
import importlib.metadata
import importlib.util
import json
import math
import os
import pickle
import random
import signal
import sys
import time
import tomllib
import traceback
from collections import defaultdict, deque
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, ClassVar

ROOT = Path(__file__).resolve().parents[1]
ALLOWLIST = Path(__file__).with_name("input_gate_allowlist.toml")
#: Bumped when what a trace records changes (the trace cache is keyed by it and the sources).
TOOL_VERSION = "2"

#: The probe: a literal moves by DELTA relative (x -> x (1 +- DELTA)); a float zero by
#: +-ZERO_STEP; an integer by a whole step at least.
DELTA = 1e-3
ZERO_STEP = 1e-3
#: The change a verdict is judged at: SCALE relative (10 %). A modelling constant's other
#: readings lie 0.1 % to 50 % away (a mean Earth radius against WGS-84's semi-major axis, the
#: pencil-beam rule's 27000 against 32400 or 41253); a probe of 0.1 % keeps the response
#: linear, so a literal's effect is the probe's, scaled by SCALE / (the probe's relative size).
SCALE = 0.1
#: An order of magnitude: the other readings of a value the paper does not give can lie that far
#: (an initial GPS fix of 3 m or 30 m, a receiver clock's noise two decades apart). A literal
#: whose probe says a factor FACTOR could matter is also evaluated at x FACTOR and / FACTOR.
FACTOR = 10.0
#: A literal is flagged when a SCALE change of it moves a claim by more than this many
#: tolerances (linearised from the probe), when x FACTOR or / FACTOR does, or when the probe,
#: a SCALE change or a FACTOR change flips a statement.
FLAG_TOLERANCES = 0.1
#: A group of literals is split when its probe moves a claim by more than this many
#: tolerances: a tenth of what, linearised to a FACTOR change, would reach the flag (so that
#: literals that partly cancel in a group are still found).
GROUP_TOLERANCES = FLAG_TOLERANCES * DELTA / (FACTOR - 1) / 10
#: A statement's numbers "move" when the probe changes them by more than this relative amount
#: (an elasticity of 0.1; a group is then split), and a single literal that moves them by more
#: than STATEMENT_REPORT_REL is reported and also tried at +-SCALE (does the statement flip?).
STATEMENT_GROUP_REL = 1e-4
STATEMENT_REPORT_REL = 1e-4
#: A numeric claim with an exact (zero) tolerance moves when it changes by more than this
#: relative amount (rounding of the arithmetic is not a move).
EXACT_FLOOR_REL = 1e-9

#: Modules of the package whose numbers are never candidates, with the reason.
EXCLUDED_MODULES: dict[str, str] = {
    "ledger": "the ledger's machinery (verdicts, rendering, caches), not a model",
    "figures": "figures draw what the models compute; no claim reads them",
    "book": "the book's build helpers",
    "diagrams": "block diagrams drawn on the pages",
    "traceability": "the traceability index",
    "trace": "the @implements registry",
    "coverage": "the coverage accounting of printed items",
    "__main__": "the command line",
    "_validate": "input validation: its bounds raise on bad input, they never make a value",
}

#: The rules that keep a literal out of the candidates, with their reasons (committed and
#: reviewable; ``--audit`` perturbs these literals too and reports what they move).
RULES: dict[str, str] = {
    "text": "inside an f-string or a message: it formats text, it does not make a value",
    "raise": "inside a raise or assert statement, or an argument of a validation call (require_..., "
    "check_...): a check that raises on bad input, not a value",
    "annotation": "a type annotation",
    "declared-input": "the value, range or grid of a declared input (InputSet.published/convention/"
    "assumed/fitted): the ledger records it as an input",
    "claim-metadata": "a claim's published value, relation or tolerance (Claim, Erratum, Tolerance, "
    "printed, prose, figure_reading, monte_carlo): fixed by the printed text, never computed from",
    "index": "an index, slice, dict key, shape, axis, count of dimensions or range() bound: the "
    "structure of an array or a loop, not a quantity",
    "exponent": "an integer, half-, third- or quarter-integer exponent up to 4 (a square, a cube, a "
    "square root, Kepler's 3/2): the form of the formula; a non-simple exponent (a fitted power "
    "law) stays a candidate",
    "identity": "0, 1 or -1 in an expression (an additive or multiplicative identity, a complement "
    "1 - p, a sign, a start value), in a pattern of integer 0/1/-1 (a code, a mask), or a default "
    "of 1 that the function only multiplies by (a scale knob: the declared quantities as they are); "
    "at module level, as a dataclass field, as any other default or as a keyword value it stays a "
    "candidate",
    "formula-coefficient": "a small integer factor (2 to 12) or a simple fraction (1/2, 1/4, 3/4, 3/2, "
    "5/2) as a direct operand of * or /, a small integer (int-typed) of + or -, or either side of a "
    "ratio of two integers (8.0 / 27.0): the structure of an equation (2 pi f, sigma^2 / 2, 4 pi, "
    "n - 1, a closed form's exact fraction); as a default, module constant, keyword or plain "
    "argument it stays a candidate",
    "exact-symbolic": "an argument of an exact or symbolic constructor (Fraction, sympy's Rational, "
    "series, coeff, diff, factorial, binomial): an exact number, or the order of an expansion or a "
    "derivative",
    "decibel": "10 or 20 in a decibel conversion (10 log10, 20 log10, 10 ** (x / 10)): exact by the "
    "definition of the decibel",
    "unit-conversion": "a power of ten (1e-12 to 1e12), 60, 3600, 86400, 180 or 360 as a direct operand "
    "of * or /: an exact conversion (km, ms, MHz, minutes, hours, days, degrees); a scenario value "
    "written as such a number (a 1000-look count as a call argument) stays a candidate",
    "seed": "a random seed (an argument of default_rng, RandomState or SeedSequence, or bound to a "
    "name containing 'seed'): it selects the draws, the Monte Carlo tolerance covers their spread",
}


# ------------------------------------------------------------------------------------------
# The package to check and its claims
# ------------------------------------------------------------------------------------------
@dataclass
class Target:
    """What the gate checks: a package's numbers against the claims of some of its modules.

    Attributes
    ----------
    package : str
        Top-level package name (``"navcore"``); its modules are the candidates' home, and a
        perturbed child imports all of them afresh.
    root : Path
        The package's directory.
    claim_modules : callable
        Returns the names of the modules that define ``CLAIMS`` lists (called in a child).
    repo : Path
        Paths in the report are relative to it.
    exclude : dict
        Module names (relative to the package, dotted prefixes) whose numbers are never
        candidates, with the reason.
    exposure_prefix : str
        Module-name prefix of the paper modules whose functions' returned numbers a
        statement exposes.
    allowlist : Path or None
        The allowlist file.
    """

    package: str
    root: Path
    claim_modules: Callable[[], list[str]]
    repo: Path = ROOT
    exclude: dict[str, str] = field(default_factory=dict)
    exposure_prefix: str = ""
    allowlist: Path | None = None


def _navcore_claim_modules() -> list[str]:
    from navcore.ledger.registry import paper_modules

    return list(paper_modules())


def navcore_target() -> Target:
    """The default target: navcore's library and paper modules against the whole ledger."""
    return Target(
        package="navcore",
        root=ROOT / "navcore",
        claim_modules=_navcore_claim_modules,
        repo=ROOT,
        exclude=EXCLUDED_MODULES,
        exposure_prefix="navcore.papers.",
        allowlist=ALLOWLIST,
    )


# ------------------------------------------------------------------------------------------
# Static index: candidates, execution units, names
# ------------------------------------------------------------------------------------------
Ref = tuple[str, ...]  # a name ("X",) or a dotted chain ("units", "FT")
Symbol = tuple[str, str]  # (module, top-level name)


@dataclass
class Candidate:
    """One numeric literal of the package."""

    id: str  # "<relfile>:<line>:<col>"
    module: str
    file: str
    lineno: int
    col: int
    end_lineno: int
    end_col: int
    value: int | float
    text: str
    line_text: str
    scope: str  # enclosing function or class qualname, "<module>" at top level
    where: str  # body | default | class | module
    binding: str = ""  # the name it is bound to (constant, field, parameter, keyword), if any
    unit: int = -1  # body: the execution unit that evaluates it
    function: int = -1  # default: the function whose default (or decorator) it is
    symbols: tuple[Symbol, ...] = ()  # class/module: the top-level names it helps build
    rule: str = ""  # the exclusion rule that applies, if any
    allow: dict[str, str] | None = None  # the allowlist entry that applies, if any

    @property
    def position(self) -> tuple[int, int, int, int]:
        return (self.lineno, self.col, self.end_lineno, self.end_col)


@dataclass
class Unit:
    """The expressions of one statement (its header, for a compound one) in a function body."""

    id: int
    file: str
    lo: int
    hi: int
    function: int
    refs: set[Ref] = field(default_factory=set)


@dataclass
class Function:
    """A def or lambda: its execution units and the names its import-time parts read."""

    id: int
    module: str
    qualname: str
    top: Symbol | None  # the top-level def/class that contains it
    units: list[int] = field(default_factory=list)
    header_refs: set[Ref] = field(default_factory=set)  # defaults and decorators


@dataclass
class ModuleInfo:
    name: str
    path: Path
    file: str  # relative to the repo
    is_package: bool
    bindings: dict[str, tuple[str, ...]] = field(default_factory=dict)
    # symbol name -> refs read where the symbol is built at import time
    deps: dict[str, set[Ref]] = field(default_factory=lambda: defaultdict(set))
    # module-level statements without a symbol: their candidates apply when the module runs
    units_by_line: list[tuple[int, int, int]] = field(default_factory=list)  # (lo, hi, unit id)


@dataclass
class Index:
    """Everything the gate knows about the package before running anything."""

    target: Target
    modules: dict[str, ModuleInfo] = field(default_factory=dict)
    candidates: list[Candidate] = field(default_factory=list)
    units: list[Unit] = field(default_factory=list)
    functions: list[Function] = field(default_factory=list)
    excluded_modules: dict[str, str] = field(default_factory=dict)

    def candidate(self, cid: str) -> Candidate:
        return self._by_id[cid]

    def finish(self) -> None:
        self._by_id = {c.id: c for c in self.candidates}
        self._units_by_file: dict[str, list[Unit]] = defaultdict(list)
        for u in self.units:
            self._units_by_file[u.file].append(u)


def _literal_value(node: ast.AST) -> int | float | None:
    """The number a literal node writes (``-x`` included), else None."""
    if isinstance(node, ast.Constant) and type(node.value) in (int, float):
        return node.value  # type: ignore[no-any-return]
    if (
        isinstance(node, ast.UnaryOp)
        and isinstance(node.op, ast.USub | ast.UAdd)
        and isinstance(node.operand, ast.Constant)
        and type(node.operand.value) in (int, float)
    ):
        v = node.operand.value
        return -v if isinstance(node.op, ast.USub) else v
    return None


def _ref(node: ast.AST) -> Ref | None:
    """A Name or a dotted Attribute chain on a Name, as a tuple of parts."""
    parts: list[str] = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if isinstance(node, ast.Name):
        parts.append(node.id)
        return tuple(reversed(parts))
    return None


_STMT_LIST_FIELDS = ("body", "orelse", "finalbody", "handlers", "cases")
_DECLARE = {"published", "convention", "assumed", "fitted"}
_METADATA_CALLS = {"Claim", "Erratum", "Tolerance", "printed", "prose", "figure_reading", "monte_carlo"}
_SHAPE_CALLS = {
    "zeros",
    "ones",
    "empty",
    "full",
    "eye",
    "identity",
    "reshape",
    "zeros_like",
    "ones_like",
    "tile",
    "repeat",
    "ndindex",
    "broadcast_to",
    "atleast_1d",
    "atleast_2d",
    "split",
    "array_split",
    "moveaxis",
    "swapaxes",
    "expand_dims",
    "squeeze",
    "transpose",
    "roll",
    "diagonal",
    "trace",
    "kron",
}
_SHAPE_KEYWORDS = {
    "axis",
    "axes",
    "ndim",
    "ddof",
    "k",
    "ord",
    "axis1",
    "axis2",
    "ndmin",
    "minlength",
    "size",
    "shape",
}
#: Random draws: a literal in a tuple argument is the shape of the draw.
_DRAW_CALLS = {
    "standard_normal",
    "normal",
    "uniform",
    "random",
    "integers",
    "choice",
    "multivariate_normal",
    "exponential",
    "rayleigh",
    "chisquare",
    "standard_exponential",
    "permutation",
}
_SEED_CALLS = {"default_rng", "RandomState", "SeedSequence", "seed", "Generator", "PCG64"}
_STRUCTURE_ATTRS = {"shape", "size", "ndim"}
#: Exact and symbolic constructors: their arguments are exact numbers or orders.
_EXACT_CALLS = {"Rational", "Fraction", "Integer", "series", "coeff", "diff", "factorial", "binomial", "comb"}
_CONVERSIONS = {60.0, 3600.0, 86400.0, 180.0, 360.0}
_FRACTIONS = {0.5, 0.25, 0.75, 1.5, 2.5}


def _is_structure(node: ast.AST) -> bool:
    """An expression about array structure: len(...), x.shape/size/ndim, np.ndim(x)."""
    for sub in ast.walk(node):
        if isinstance(sub, ast.Call):
            name = _ref(sub.func)
            if name and name[-1] in ("len", "ndim", "size", "shape", "matrix_rank"):
                return True
        if isinstance(sub, ast.Attribute) and sub.attr in _STRUCTURE_ATTRS:
            return True
    return False


def _simple_exponent(v: float) -> bool:
    return abs(v) <= 4 and any(abs(v * d - round(v * d)) < 1e-12 for d in (1, 2, 3, 4))


def _mentions_log10(node: ast.AST) -> bool:
    for sub in ast.walk(node):
        if isinstance(sub, ast.Call):
            name = _ref(sub.func)
            if name and (name[-1] == "log10" or "db" in name[-1].lower()):
                return True
        if (
            isinstance(sub, ast.BinOp)
            and isinstance(sub.op, ast.Pow)
            and _literal_value(sub.left) in (10, 10.0)
        ):
            return True
        if isinstance(sub, ast.Call):
            name = _ref(sub.func)
            if name and name[-1] == "power" and sub.args and _literal_value(sub.args[0]) in (10, 10.0):
                return True
    return False


def classify_rule(node: ast.AST, parents: dict[ast.AST, ast.AST], where: str, binding: str) -> str:
    """The exclusion rule (a key of :data:`RULES`) that applies to a literal, or ``""``.

    ``where`` is ``body``, ``default``, ``class`` or ``module``; ``binding`` the name the
    literal is bound to (a constant, a field, a parameter, a keyword), if any.
    """
    value = _literal_value(node)
    assert value is not None
    chain: list[ast.AST] = []
    cur: ast.AST | None = node
    while cur is not None:
        chain.append(cur)
        cur = parents.get(cur)
    # text, checks, annotations, declarations, claim metadata (anywhere up the chain, up to
    # the nearest function or lambda that would run the literal as code)
    child = node
    for anc in chain[1:]:
        if isinstance(anc, ast.JoinedStr | ast.FormattedValue):
            return "text"
        if isinstance(anc, ast.Raise | ast.Assert):
            return "raise"
        if isinstance(anc, ast.arg) or (isinstance(anc, ast.AnnAssign) and child is anc.annotation):
            return "annotation"
        if isinstance(anc, ast.FunctionDef | ast.AsyncFunctionDef) and child is anc.returns:
            return "annotation"
        if isinstance(anc, ast.Call):
            name = _ref(anc.func)
            last = name[-1] if name else ""
            if last in _DECLARE and isinstance(anc.func, ast.Attribute):
                return "declared-input"
            if last in _METADATA_CALLS or name == ("Claim", "statement"):
                # a compute lambda inside Claim(...) is code: only direct metadata counts
                if not any(isinstance(a, ast.Lambda) for a in chain[1 : chain.index(anc)]):
                    return "claim-metadata"
            if last in ("warn", "print", "format", "debug", "info", "warning", "error"):
                return "text"
            if last.startswith(("require_", "check_", "_require", "_check")):
                return "raise"
        if isinstance(anc, ast.Lambda | ast.FunctionDef | ast.AsyncFunctionDef | ast.Module):
            break
        child = anc
    if binding and "seed" in binding.lower():
        return "seed"
    parent = parents.get(node)
    if isinstance(parent, ast.Dict) and node in parent.keys:
        return "index"
    if (
        isinstance(parent, ast.Tuple | ast.List)
        and len(parent.elts) >= 2
        and all(_literal_value(e) in (0, 1, -1) and type(_literal_value(e)) is int for e in parent.elts)
    ):
        return "identity"  # a sign or selection pattern (a Barker code, a mask)
    # indices, shapes, range bounds
    child = node
    for anc in chain[1:]:
        if isinstance(anc, ast.Subscript) and child is anc.slice:
            return "index"
        if isinstance(anc, ast.Call):
            name = _ref(anc.func)
            last = name[-1] if name else ""
            if last == "range" and child in anc.args:
                return "index"
            if last in _SHAPE_CALLS and (child in anc.args or isinstance(child, ast.Tuple)):
                return "index"
            if last in _DRAW_CALLS and isinstance(child, ast.Tuple):
                return "index"
            if last in _SEED_CALLS and child in anc.args:
                return "seed"
            break
        if isinstance(anc, ast.keyword):
            if anc.arg in _SHAPE_KEYWORDS:
                return "index"
            if anc.arg and "seed" in anc.arg.lower():
                return "seed"
            break
        if isinstance(anc, ast.Compare):
            if any(_is_structure(x) for x in [anc.left, *anc.comparators]):
                return "index"  # a check of a shape, a length, a rank
            break
        if isinstance(anc, ast.stmt | ast.Lambda):
            break
        if not isinstance(anc, ast.Tuple | ast.List | ast.BinOp | ast.UnaryOp | ast.Slice):
            break
        child = anc
    if isinstance(parent, ast.BinOp) and isinstance(value, int) and _is_structure(parent):
        return "index"
    # exponents
    if isinstance(parent, ast.BinOp) and isinstance(parent.op, ast.Pow) and parent.right is node:
        if _simple_exponent(float(value)):
            return "exponent"
    if isinstance(parent, ast.Call):
        name = _ref(parent.func)
        if name and name[-1] in ("power", "pow") and len(parent.args) == 2 and parent.args[1] is node:
            if _simple_exponent(float(value)):
                return "exponent"
    fv = float(value)
    operand = isinstance(parent, ast.BinOp) or (
        isinstance(parent, ast.UnaryOp) and isinstance(parents.get(parent), ast.BinOp)
    )
    # decibels: 10 / 20 with a log10 or a power of ten nearby
    if abs(fv) in (10.0, 20.0):
        scope = parent
        for _ in range(3):
            if scope is None or isinstance(scope, ast.stmt):
                break
            if _mentions_log10(scope):
                return "decibel"
            scope = parents.get(scope)
    # 0 / 1 identities: in a function body anywhere; elsewhere only as an operand
    if fv in (0.0, 1.0, -1.0) and (where == "body" or operand):
        return "identity"
    if isinstance(parent, ast.Call):
        name = _ref(parent.func)
        if name and name[-1] in _EXACT_CALLS and node in parent.args:
            return "exact-symbolic"
    if (
        isinstance(parent, ast.BinOp)
        and isinstance(parent.op, ast.Div)
        and all(
            (v := _literal_value(side)) is not None and float(v).is_integer()
            for side in (parent.left, parent.right)
        )
    ):
        return "formula-coefficient"  # a ratio of two integers: an exact fraction (8 / 27)
    if operand and isinstance(parent, ast.BinOp):
        op = parent.op
        if isinstance(op, ast.Mult | ast.Div | ast.FloorDiv | ast.Mod):
            if fv.is_integer() and 2 <= abs(fv) <= 12:
                return "formula-coefficient"
            if abs(fv) in _FRACTIONS:
                return "formula-coefficient"
            if abs(fv) in _CONVERSIONS:
                return "unit-conversion"
            if fv != 0:
                k = math.log10(abs(fv))
                if abs(k - round(k)) < 1e-12 and abs(k) <= 12:
                    return "unit-conversion"
        if isinstance(op, ast.Add | ast.Sub) and isinstance(value, int) and 2 <= abs(value) <= 12:
            return "formula-coefficient"
    return ""


def _identity_default(
    fn: ast.FunctionDef | ast.AsyncFunctionDef,
    param: str,
    value: int | float,
    parents: dict[ast.AST, ast.AST],
) -> bool:
    """A default of 1 that the body only multiplies by: the identity (``sample_scale=1.0``: the
    declared quantities as they are). A default of 0 stays a candidate: 0 dBi, a zero bias or a
    start at the equator are assumptions, not identities."""
    if not param or value != 1:
        return False
    uses = [
        n for n in ast.walk(fn) if isinstance(n, ast.Name) and n.id == param and isinstance(n.ctx, ast.Load)
    ]
    if not uses:
        return False
    ops = (ast.Mult, ast.Div) if value == 1 else (ast.Add, ast.Sub)
    for use in uses:
        parent = parents.get(use)
        if not (isinstance(parent, ast.BinOp) and isinstance(parent.op, ops)):
            return False
        if value == 1 and isinstance(parent.op, ast.Div) and parent.left is use:
            return False
        if value == 0 and isinstance(parent.op, ast.Sub) and parent.left is use:
            return False
    return True


class _Indexer:
    """Walks one module's syntax tree: candidates, execution units, functions and names."""

    def __init__(self, index: Index, info: ModuleInfo, tree: ast.Module, source: str) -> None:
        self.index = index
        self.info = info
        self.tree = tree
        self.source = source
        self.lines = source.splitlines()
        self.parents: dict[ast.AST, ast.AST] = {}
        for parent in ast.walk(tree):
            for child in ast.iter_child_nodes(parent):
                self.parents[child] = parent
        self.module_level_any: list[Candidate] = []

    # -- bindings and imports --------------------------------------------------------------
    def _absolute(self, module: str | None, level: int) -> str:
        if level == 0:
            return module or ""
        base = self.info.name if self.info.is_package else self.info.name.rsplit(".", 1)[0]
        for _ in range(level - 1):
            base = base.rsplit(".", 1)[0]
        return f"{base}.{module}" if module else base

    def _bind_import(self, stmt: ast.Import | ast.ImportFrom) -> None:
        if isinstance(stmt, ast.Import):
            for alias in stmt.names:
                if alias.asname:
                    self.info.bindings[alias.asname] = ("module", alias.name)
                else:
                    top = alias.name.split(".")[0]
                    self.info.bindings[top] = ("module", top)
        else:
            src = self._absolute(stmt.module, stmt.level)
            for alias in stmt.names:
                if alias.name == "*":
                    continue
                self.info.bindings[alias.asname or alias.name] = ("from", src, alias.name)

    # -- expressions -----------------------------------------------------------------------
    def _scan(
        self, exprs: Iterable[ast.AST], refs: set[Ref], literals: list[ast.AST], lambdas: list[ast.Lambda]
    ) -> None:
        """Names, literals and lambdas of expressions (not descending into lambda bodies)."""
        stack = [e for e in exprs if e is not None]
        while stack:
            node = stack.pop()
            if _literal_value(node) is not None:
                literals.append(node)
                continue
            if isinstance(node, ast.Lambda):
                lambdas.append(node)
                stack.extend(d for d in node.args.defaults)
                stack.extend(d for d in node.args.kw_defaults if d is not None)
                continue
            if isinstance(node, ast.Name | ast.Attribute):
                r = _ref(node)
                if r is not None:
                    refs.add(r)
                    if isinstance(node, ast.Name):
                        continue
            if isinstance(node, ast.arg):
                continue  # annotations
            stack.extend(ast.iter_child_nodes(node))

    def _binding_of(self, node: ast.AST) -> str:
        parent = self.parents.get(node)
        if isinstance(parent, ast.keyword) and parent.arg:
            return parent.arg
        if isinstance(parent, ast.Assign) and parent.value is node:
            names = [t.id for t in parent.targets if isinstance(t, ast.Name)]
            return names[0] if names else ""
        if isinstance(parent, ast.AnnAssign) and parent.value is node and isinstance(parent.target, ast.Name):
            return parent.target.id
        if isinstance(parent, ast.arguments):
            args = [*parent.posonlyargs, *parent.args]
            if node in parent.defaults:
                i = parent.defaults.index(node)
                return args[len(args) - len(parent.defaults) + i].arg
            for a, d in zip(parent.kwonlyargs, parent.kw_defaults, strict=True):
                if d is node:
                    return a.arg
        # deeper in an expression: the name the enclosing assignment binds
        p: ast.AST | None = parent
        while p is not None and not isinstance(p, ast.stmt | ast.Lambda | ast.keyword | ast.arguments):
            p = self.parents.get(p)
        if isinstance(p, ast.keyword) and p.arg:
            return p.arg
        if isinstance(p, ast.Assign) and len(p.targets) == 1 and isinstance(p.targets[0], ast.Name):
            return p.targets[0].id
        if isinstance(p, ast.AnnAssign) and isinstance(p.target, ast.Name):
            return p.target.id
        return ""

    def _segment(self, ln: int, col: int, eln: int, ecol: int) -> str:
        """Source text of a node (columns are UTF-8 byte offsets)."""
        if ln != eln or ln - 1 >= len(self.lines):
            return ""
        return self.lines[ln - 1].encode()[col:ecol].decode(errors="replace")

    def _candidate(self, node: ast.AST, scope: str, where: str, **kw: Any) -> Candidate:
        value = _literal_value(node)
        assert value is not None
        ln, col = node.lineno, node.col_offset  # type: ignore[attr-defined]
        eln, ecol = node.end_lineno, node.end_col_offset  # type: ignore[attr-defined]
        binding = self._binding_of(node)
        if not binding and where == "class":
            p = self.parents.get(node)
            while p is not None and not isinstance(p, ast.stmt):
                p = self.parents.get(p)
            if isinstance(p, ast.AnnAssign) and isinstance(p.target, ast.Name):
                binding = p.target.id
        cand = Candidate(
            id=f"{self.info.file}:{ln}:{col}",
            module=self.info.name,
            file=self.info.file,
            lineno=ln,
            col=col,
            end_lineno=eln,
            end_col=ecol,
            value=value,
            text=self._segment(ln, col, eln, ecol) or repr(value),
            line_text=self.lines[ln - 1].strip() if ln - 1 < len(self.lines) else "",
            scope=scope,
            where=where,
            binding=binding,
            **kw,
        )
        cand.rule = classify_rule(node, self.parents, where, binding)
        self.index.candidates.append(cand)
        return cand

    # -- functions -------------------------------------------------------------------------
    def _new_function(self, qualname: str, top: Symbol | None) -> Function:
        fn = Function(id=len(self.index.functions), module=self.info.name, qualname=qualname, top=top)
        self.index.functions.append(fn)
        return fn

    def _new_unit(self, fn: Function, nodes: list[ast.AST], refs: set[Ref]) -> Unit:
        located = [n for n in nodes if hasattr(n, "lineno")]
        lo = min(n.lineno for n in located)  # type: ignore[attr-defined]
        hi = max(n.end_lineno or n.lineno for n in located)  # type: ignore[attr-defined]
        unit = Unit(id=len(self.index.units), file=self.info.file, lo=lo, hi=hi, function=fn.id, refs=refs)
        self.index.units.append(unit)
        fn.units.append(unit.id)
        return unit

    def _lambda(self, lam: ast.Lambda, outer: str, top: Symbol | None) -> None:
        fn = self._new_function(f"{outer}.<lambda:{lam.lineno}>", top)
        # defaults were scanned by the enclosing expression; record their names for the
        # lambda too (they are read when it was made, with what its body then uses)
        for d in [*lam.args.defaults, *[k for k in lam.args.kw_defaults if k is not None]]:
            self._scan([d], fn.header_refs, [], [])
        refs: set[Ref] = set()
        literals: list[ast.AST] = []
        lambdas: list[ast.Lambda] = []
        self._scan([lam.body], refs, literals, lambdas)
        unit = self._new_unit(fn, [lam.body], refs)
        for lit in literals:
            self._candidate(lit, fn.qualname, "body", unit=unit.id)
        for inner in lambdas:
            self._lambda_in_body(inner, fn, top)

    def _lambda_in_body(self, lam: ast.Lambda, fn: Function, top: Symbol | None) -> None:
        self._lambda(lam, fn.qualname, top)

    def _function_def(
        self, stmt: ast.FunctionDef | ast.AsyncFunctionDef, outer_qual: str, top: Symbol | None
    ) -> Function:
        qual = f"{outer_qual}.{stmt.name}" if outer_qual else stmt.name
        fn = self._new_function(qual, top)
        self._statements(stmt.body, fn, qual, top)
        return fn

    # -- statements ------------------------------------------------------------------------
    def _header(self, stmt: ast.stmt) -> list[ast.AST]:
        """The expressions a statement evaluates itself (not its nested statement lists)."""
        out: list[ast.AST] = []
        for name, value in ast.iter_fields(stmt):
            if name in _STMT_LIST_FIELDS:
                if name == "handlers":
                    out.extend(h.type for h in value if h.type is not None)
                if name == "cases":
                    for case in value:
                        out.append(case.pattern)
                        if case.guard is not None:
                            out.append(case.guard)
                continue
            if name in ("annotation", "returns", "type_comment"):
                continue
            if isinstance(value, ast.AST):
                out.append(value)
            elif isinstance(value, list):
                out.extend(v for v in value if isinstance(v, ast.AST))
        # operators and contexts carry no position; keywords, aliases and the like do
        return [n for n in out if hasattr(n, "lineno")]

    def _sub_statement_lists(self, stmt: ast.stmt) -> list[list[ast.stmt]]:
        out = []
        for name in _STMT_LIST_FIELDS:
            value = getattr(stmt, name, None)
            if not value:
                continue
            if name == "handlers":
                out.extend(h.body for h in value)
            elif name == "cases":
                out.extend(c.body for c in value)
            else:
                out.append(value)
        return out

    def _statements(self, stmts: list[ast.stmt], fn: Function, qual: str, top: Symbol | None) -> None:
        """Statements of a function body: each becomes an execution unit."""
        for stmt in stmts:
            if isinstance(stmt, ast.FunctionDef | ast.AsyncFunctionDef):
                exprs: list[ast.AST] = [
                    *stmt.decorator_list,
                    *stmt.args.defaults,
                    *[d for d in stmt.args.kw_defaults if d is not None],
                ]
                refs: set[Ref] = set()
                literals: list[ast.AST] = []
                lambdas: list[ast.Lambda] = []
                self._scan(exprs, refs, literals, lambdas)
                unit = self._new_unit(fn, [stmt, *exprs], refs)
                unit.hi = stmt.body[0].lineno - 1 if stmt.body[0].lineno > stmt.lineno else stmt.lineno
                for lit in literals:
                    self._candidate(lit, qual, "body", unit=unit.id)
                for lam in lambdas:
                    self._lambda(lam, qual, top)
                inner = self._function_def(stmt, qual, top)
                inner.header_refs |= refs
                continue
            if isinstance(stmt, ast.ClassDef):  # a class inside a function: its body runs now
                exprs = [*stmt.decorator_list, *stmt.bases, *[k.value for k in stmt.keywords]]
                refs = set()
                literals = []
                lambdas = []
                self._scan(exprs, refs, literals, lambdas)
                if exprs:
                    unit = self._new_unit(fn, [stmt, *exprs], refs)
                    for lit in literals:
                        self._candidate(lit, qual, "body", unit=unit.id)
                self._statements(stmt.body, fn, f"{qual}.{stmt.name}", top)
                continue
            header = self._header(stmt)
            refs = set()
            literals = []
            lambdas = []
            self._scan(header, refs, literals, lambdas)
            if header or isinstance(stmt, ast.Return | ast.Pass | ast.Break | ast.Continue):
                nodes: list[ast.AST] = header if header else [stmt]
                unit = self._new_unit(fn, nodes, refs)
                if not header:
                    unit.lo = unit.hi = stmt.lineno
                for lit in literals:
                    self._candidate(lit, qual, "body", unit=unit.id)
            for lam in lambdas:
                self._lambda(lam, qual, top)
            for sub in self._sub_statement_lists(stmt):
                self._statements(sub, fn, qual, top)

    def _defined_names(self, stmt: ast.stmt) -> set[str]:
        """Top-level names a module-level statement binds or mutates (X = ..., X.append(...))."""
        names: set[str] = set()

        def targets(t: ast.AST) -> None:
            if isinstance(t, ast.Name):
                names.add(t.id)
            elif isinstance(t, ast.Tuple | ast.List):
                for e in t.elts:
                    targets(e)
            elif isinstance(t, ast.Starred):
                targets(t.value)
            elif isinstance(t, ast.Attribute | ast.Subscript):
                base = t
                while isinstance(base, ast.Attribute | ast.Subscript):
                    base = base.value
                if isinstance(base, ast.Name):
                    names.add(base.id)

        if isinstance(stmt, ast.Assign):
            for t in stmt.targets:
                targets(t)
        elif isinstance(stmt, ast.AnnAssign | ast.AugAssign):
            targets(stmt.target)
        elif isinstance(stmt, ast.For | ast.AsyncFor):
            targets(stmt.target)
        elif isinstance(stmt, ast.With | ast.AsyncWith):
            for item in stmt.items:
                if item.optional_vars is not None:
                    targets(item.optional_vars)
        elif isinstance(stmt, ast.Expr):
            for sub in ast.walk(stmt.value):
                if isinstance(sub, ast.Call) and isinstance(sub.func, ast.Attribute):
                    base = sub.func.value
                    while isinstance(base, ast.Attribute | ast.Subscript):
                        base = base.value
                    if isinstance(base, ast.Name):
                        names.add(base.id)
                    break
        return names

    def _import_time(self, stmts: list[ast.stmt], where: str, symbols: set[str] | None, qual: str) -> None:
        """Module-level or class-body statements: evaluated when the module is imported."""
        for stmt in stmts:
            if isinstance(stmt, ast.Import | ast.ImportFrom):
                if where == "module":
                    self._bind_import(stmt)
                continue
            if isinstance(stmt, ast.FunctionDef | ast.AsyncFunctionDef):
                sym = stmt.name if where == "module" else None
                top: Symbol | None = (self.info.name, sym) if sym else None
                if where == "class" and symbols:
                    top = (self.info.name, sorted(symbols)[0])
                exprs = [
                    *stmt.decorator_list,
                    *stmt.args.defaults,
                    *[d for d in stmt.args.kw_defaults if d is not None],
                ]
                refs: set[Ref] = set()
                literals: list[ast.AST] = []
                lambdas: list[ast.Lambda] = []
                self._scan(exprs, refs, literals, lambdas)
                fq = f"{qual}.{stmt.name}" if qual else stmt.name
                fn = self._function_def(stmt, qual, top)
                fn.header_refs |= refs
                for lit in literals:
                    cand = self._candidate(lit, fq, "default", function=fn.id)
                    if not cand.rule and _identity_default(stmt, cand.binding, cand.value, self.parents):
                        cand.rule = "identity"
                for lam in lambdas:
                    self._lambda(lam, fq, top)
                if where == "module":
                    self.info.bindings[stmt.name] = ("def",)
                    self.info.deps[stmt.name] |= refs
                elif symbols:
                    for s in symbols:
                        self.info.deps[s] |= refs
                continue
            if isinstance(stmt, ast.ClassDef):
                cq = f"{qual}.{stmt.name}" if qual else stmt.name
                syms = {stmt.name} if where == "module" else set(symbols or ())
                exprs = [*stmt.decorator_list, *stmt.bases, *[k.value for k in stmt.keywords]]
                refs = set()
                literals = []
                lambdas = []
                self._scan(exprs, refs, literals, lambdas)
                for s in syms:
                    self.info.deps[s] |= refs
                for lit in literals:
                    self._candidate(
                        lit, cq, "class", symbols=tuple((self.info.name, s) for s in sorted(syms))
                    )
                for lam in lambdas:
                    self._lambda(lam, cq, (self.info.name, sorted(syms)[0]) if syms else None)
                if where == "module":
                    self.info.bindings[stmt.name] = ("class",)
                self._import_time(stmt.body, "class", syms, cq)
                continue
            header = self._header(stmt)
            refs = set()
            literals = []
            lambdas = []
            self._scan(header, refs, literals, lambdas)
            if where == "module":
                defined = self._defined_names(stmt)
                for name in defined:
                    self.info.deps[name] |= refs
                    if name not in self.info.bindings:
                        self.info.bindings[name] = ("value",)
                syms = tuple((self.info.name, n) for n in sorted(defined))
                scope_q = "<module>"
            else:
                syms = tuple((self.info.name, s) for s in sorted(symbols or ()))
                for s in symbols or ():
                    self.info.deps[s] |= refs
                scope_q = qual
            for lit in literals:
                self._candidate(lit, scope_q, where, symbols=syms)
            # a lambda made at import time (a claim's compute) uses what its body and defaults
            # read, not everything the statement that holds it builds (a whole CLAIMS list)
            top = syms[0] if (syms and where == "class") else None
            for lam in lambdas:
                self._lambda(lam, scope_q, top)
            # nested statement lists (if/for/with/try at module level) are import-time too
            for sub in self._sub_statement_lists(stmt):
                if where == "module" and isinstance(stmt, ast.For | ast.AsyncFor | ast.With | ast.AsyncWith):
                    # what the loop body builds depends on what the loop iterates over
                    loop_targets = self._defined_names(stmt)
                    before = {k: set(v) for k, v in self.info.deps.items()}
                    self._import_time(sub, where, symbols, qual)
                    for name, deps in self.info.deps.items():
                        if deps != before.get(name, set()):
                            deps |= {(t,) for t in loop_targets}
                else:
                    self._import_time(sub, where, symbols, qual)

    def run(self) -> None:
        self._import_time(self.tree.body, "module", None, "")


def _module_name(package: str, root: Path, path: Path) -> tuple[str, bool]:
    rel = path.relative_to(root).with_suffix("")
    parts = [package, *rel.parts]
    if parts[-1] == "__init__":
        return ".".join(parts[:-1]), True
    return ".".join(parts), False


def load_allowlist(path: Path | None) -> list[dict[str, str]]:
    """The allowlist entries: ``file`` and ``name`` (or ``text``), each with its ``reason``.

    Raises
    ------
    ValueError
        If an entry lacks its file, its name or text, or its reason.
    """
    if path is None or not path.exists():
        return []
    data = tomllib.loads(path.read_text())
    entries = data.get("allow", [])
    for e in entries:
        if not e.get("file") or not (e.get("name") or e.get("text")) or not str(e.get("reason", "")).strip():
            raise ValueError(f"allowlist entry {e!r} needs a file, a name or text, and a reason")
    return entries  # type: ignore[no-any-return]


def _allowed(cand: Candidate, entries: list[dict[str, str]]) -> dict[str, str] | None:
    for e in entries:
        if e["file"] != cand.file:
            continue
        if e.get("name") and e["name"] != cand.binding:
            continue
        if e.get("text") and e["text"] != cand.text:
            continue
        if e.get("scope") and e["scope"] != cand.scope:
            continue
        return e
    return None


def index_package(target: Target) -> Index:
    """Parse every module of the package: its candidates, execution units, functions and names."""
    index = Index(target=target)
    allow = load_allowlist(target.allowlist)
    for path in sorted(target.root.rglob("*.py")):
        if any(part.startswith(".") or part == "__pycache__" for part in path.parts):
            continue
        name, is_pkg = _module_name(target.package, target.root, path)
        rel = name[len(target.package) + 1 :] if name != target.package else ""
        reason = next(
            (r for prefix, r in target.exclude.items() if rel == prefix or rel.startswith(prefix + ".")), None
        )
        try:
            file = str(path.relative_to(target.repo))
        except ValueError:
            file = str(path)
        info = ModuleInfo(name=name, path=path, file=file, is_package=is_pkg)
        index.modules[name] = info
        source = path.read_text()
        tree = ast.parse(source, str(path))
        walker = _Indexer(index, info, tree, source)
        before = len(index.candidates)
        walker.run()
        if reason is not None:
            index.excluded_modules[name] = reason
            del index.candidates[before:]  # names and units stay: they carry usage
    for cand in index.candidates:
        cand.allow = _allowed(cand, allow)
    index.finish()
    return index


# ------------------------------------------------------------------------------------------
# Name resolution and relevance
# ------------------------------------------------------------------------------------------
class Resolver:
    """Resolves names read in a module to the package's top-level symbols."""

    def __init__(self, index: Index) -> None:
        self.index = index
        self._cache: dict[tuple[str, Ref], tuple[Symbol, ...]] = {}

    def _is_module(self, name: str) -> bool:
        return name in self.index.modules

    def _binding(self, module: str, name: str, depth: int = 0) -> tuple[str, str] | None:
        """("module", modname) or ("symbol", module, name) for a name bound in ``module``."""
        info = self.index.modules.get(module)
        if info is None or depth > 20:
            return None
        b = info.bindings.get(name)
        if b is None:
            if info.is_package and self._is_module(f"{module}.{name}"):
                return ("module", f"{module}.{name}")
            return None
        if b[0] == "module":
            return ("module", b[1]) if self._is_module(b[1]) else None
        if b[0] == "from":
            src, attr = b[1], b[2]
            if self._is_module(f"{src}.{attr}"):
                return ("module", f"{src}.{attr}")
            if not self._is_module(src):
                return None
            return self._binding(src, attr, depth + 1)
        return ("symbol", module, name)  # type: ignore[return-value]

    def resolve(self, module: str, ref: Ref) -> tuple[Symbol, ...]:
        key = (module, ref)
        if key in self._cache:
            return self._cache[key]
        out: tuple[Symbol, ...] = ()
        b = self._binding(module, ref[0])
        rest = list(ref[1:])
        while b is not None:
            if b[0] == "symbol":
                out = ((b[1], b[2]),)  # type: ignore[misc]
                break
            mod = b[1]
            if not rest:
                break
            attr = rest.pop(0)
            b = self._binding(mod, attr)
            if b is None and self._is_module(f"{mod}.{attr}"):
                b = ("module", f"{mod}.{attr}")
        self._cache[key] = out
        return out

    def closure(self, seeds: Iterable[Symbol]) -> set[Symbol]:
        """The symbols ``seeds`` read at import time, transitively."""
        seen: set[Symbol] = set()
        stack = list(seeds)
        while stack:
            sym = stack.pop()
            if sym in seen:
                continue
            seen.add(sym)
            info = self.index.modules.get(sym[0])
            if info is None:
                continue
            for ref in info.deps.get(sym[1], ()):
                stack.extend(self.resolve(sym[0], ref))
        return seen


@dataclass
class Relevance:
    """Which claims each candidate can move (from the traces), and what each claim ran."""

    claims_of: dict[str, set[str]]
    units_run: dict[str, set[int]]
    used: dict[str, set[Symbol]]


def relevance(index: Index, traces: dict[str, dict[str, Any]], candidates: list[Candidate]) -> Relevance:
    """Map candidates to the claims whose nominal evaluation ran them (see the module doc)."""
    resolver = Resolver(index)
    units_by_file: dict[str, list[Unit]] = defaultdict(list)
    for u in index.units:
        units_by_file[u.file].append(u)
    fn_module = {f.id: f.module for f in index.functions}
    units_run: dict[str, set[int]] = {}
    used_syms: dict[str, set[Symbol]] = {}
    modules_run: dict[str, set[str]] = {}
    for cid, tr in traces.items():
        ran: set[int] = set()
        for file, lines in (tr.get("lines") or {}).items():
            ls = sorted(lines)
            for u in units_by_file.get(file, ()):
                i = bisect.bisect_left(ls, u.lo)
                if i < len(ls) and ls[i] <= u.hi:
                    ran.add(u.id)
        units_run[cid] = ran
        funcs = {index.units[u].function for u in ran}
        seeds: set[Symbol] = set()
        for u in ran:
            unit = index.units[u]
            mod = fn_module[unit.function]
            for ref in unit.refs:
                seeds.update(resolver.resolve(mod, ref))
        for f in funcs:
            fn = index.functions[f]
            if fn.top is not None:
                seeds.add(fn.top)
            for ref in fn.header_refs:
                seeds.update(resolver.resolve(fn.module, ref))
        used_syms[cid] = resolver.closure(seeds)
        modules_run[cid] = {fn_module[index.units[u].function] for u in ran}
    by_unit: dict[int, set[str]] = defaultdict(set)
    by_function: dict[int, set[str]] = defaultdict(set)
    by_symbol: dict[Symbol, set[str]] = defaultdict(set)
    by_module: dict[str, set[str]] = defaultdict(set)
    for cid, ran in units_run.items():
        for u in ran:
            by_unit[u].add(cid)
            by_function[index.units[u].function].add(cid)
        for sym in used_syms[cid]:
            by_symbol[sym].add(cid)
        for mod in modules_run[cid]:
            by_module[mod].add(cid)
    claims_of: dict[str, set[str]] = {}
    for cand in candidates:
        if cand.where == "body":
            out = set(by_unit.get(cand.unit, ()))
        elif cand.where == "default":
            out = set(by_function.get(cand.function, ()))
        elif cand.symbols:
            out = set().union(*(by_symbol.get(s, set()) for s in cand.symbols))
        else:
            out = set(by_module.get(cand.module, ()))
        claims_of[cand.id] = out
    return Relevance(claims_of=claims_of, units_run=units_run, used=used_syms)


# ------------------------------------------------------------------------------------------
# Processes: a fork per task, two at a time
# ------------------------------------------------------------------------------------------
@dataclass
class Task:
    key: str
    fn: Callable[..., Any]
    args: tuple[Any, ...]
    timeout: float
    on_done: Callable[[Any, str | None], None]
    capture: bool = True  # the child's output goes to its log file (else to the parent's)


def _exit_on_signal(signum: int, frame: Any) -> None:
    raise SystemExit(128 + signum)


class Scheduler:
    """Runs tasks in forked children, ``jobs`` at a time; a task's callback may submit more."""

    def __init__(self, jobs: int, workdir: Path, nice: int = 0, log: Callable[[str], None] = print) -> None:
        self.jobs = max(1, jobs)
        self.workdir = workdir
        self.nice = nice
        self.log = log
        self.queue: deque[Task] = deque()
        self.running: dict[int, tuple[Task, Path, float]] = {}
        self.n = 0
        self.done = 0

    def submit(self, task: Task) -> None:
        self.queue.append(task)

    def _start(self, task: Task) -> None:
        self.n += 1
        out = self.workdir / f"task-{os.getpid()}-{self.n}.pkl"
        logf = self.workdir / f"task-{os.getpid()}-{self.n}.log"
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
        if pid == 0:  # child
            code = 0
            try:
                signal.signal(signal.SIGINT, signal.SIG_DFL)
                signal.signal(signal.SIGTERM, _exit_on_signal)  # a child that forks cleans up its own
                if self.nice:
                    os.nice(self.nice)
                if task.capture:
                    fd = os.open(logf, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
                    os.dup2(fd, 1)
                    os.dup2(fd, 2)
                try:
                    res: tuple[str, Any] = ("ok", task.fn(*task.args))
                except BaseException:
                    res = ("error", traceback.format_exc())
                    code = 1
                tmp = out.with_suffix(".tmp")
                with open(tmp, "wb") as fh:
                    pickle.dump(res, fh)
                os.replace(tmp, out)
                sys.stdout.flush()
                sys.stderr.flush()
            finally:
                os._exit(code)
        self.running[pid] = (task, out, time.monotonic())

    def _finish(self, pid: int, timed_out: bool = False) -> None:
        task, out, _ = self.running.pop(pid)
        self.done += 1
        logf = out.with_suffix(".log")
        if timed_out:
            result, error = None, f"timed out after {task.timeout:.0f} s"
        elif out.exists():
            with open(out, "rb") as fh:
                status, payload = pickle.load(fh)
            result, error = (payload, None) if status == "ok" else (None, payload)
        else:
            tail = logf.read_text()[-2000:] if logf.exists() else ""
            result, error = None, f"the child died without a result: {tail}"
        out.unlink(missing_ok=True)
        if error is None:
            logf.unlink(missing_ok=True)
        task.on_done(result, error)

    def run(self) -> None:
        try:
            while self.queue or self.running:
                while self.queue and len(self.running) < self.jobs:
                    self._start(self.queue.popleft())
                pid, _status = os.waitpid(-1, os.WNOHANG)
                if pid and pid in self.running:
                    self._finish(pid)
                    continue
                now = time.monotonic()
                for p, (task, _out, t0) in list(self.running.items()):
                    if now - t0 > task.timeout:
                        with contextlib.suppress(ProcessLookupError):
                            os.kill(p, signal.SIGKILL)
                        os.waitpid(p, 0)
                        self._finish(p, timed_out=True)
                time.sleep(0.02)
        except BaseException:
            for p in list(self.running):
                with contextlib.suppress(ProcessLookupError):
                    os.kill(p, signal.SIGTERM)
            deadline = time.monotonic() + 5.0
            while self.running and time.monotonic() < deadline:
                for p in list(self.running):
                    with contextlib.suppress(ChildProcessError):
                        if os.waitpid(p, os.WNOHANG)[0]:
                            del self.running[p]
                time.sleep(0.05)
            for p in list(self.running):
                with contextlib.suppress(ProcessLookupError):
                    os.kill(p, signal.SIGKILL)
                with contextlib.suppress(ChildProcessError):
                    os.waitpid(p, 0)
            self.running.clear()
            raise


# ------------------------------------------------------------------------------------------
# What runs in the children
# ------------------------------------------------------------------------------------------
def _load_claims(target: Target) -> dict[str, tuple[Any, str]]:
    """Import the claim modules: claim id -> (claim, defining module)."""
    out: dict[str, tuple[Any, str]] = {}
    for name in target.claim_modules():
        module = importlib.import_module(name)
        for c in getattr(module, "CLAIMS", ()):
            out[c.id] = (c, name)
    return out


def _canonical(value: Any) -> str:
    from navcore.claims.json_coding import jsonable

    try:
        return json.dumps(jsonable(value), sort_keys=True)
    except (TypeError, ValueError):
        return repr(value)


def claims_metadata(target: Target) -> dict[str, Any]:
    """Run in a child: every claim's paper, module, published value and tolerance; the third-party
    modules the package imports (the perturbation parent preloads them)."""
    from navcore.claims.declarations import resolve_tolerance

    claims = _load_claims(target)
    meta = {}
    for cid, (c, module) in claims.items():
        try:
            tol = resolve_tolerance(c)
            allowed = float(tol.allowed(float(c.published))) if not c.is_statement else 0.0
            policy = tol.policy
        except Exception as exc:  # a claim whose tolerance fails is the ledger's business
            allowed, policy = float("nan"), f"error: {exc}"
        meta[cid] = {
            "paper": c.paper,
            "module": module,
            "published": c.published if isinstance(c.published, bool) else float(c.published),
            "statement": bool(c.is_statement),
            "computes": c.compute is not None,
            "allowed": allowed,
            "policy": policy,
            "relation": c.relation,
            "unit": c.unit,
            "quantity": c.quantity,
        }
    pkg = target.package
    third = sorted(m for m in sys.modules if m != pkg and not m.startswith(pkg + ".") and m != "__main__")
    return {"claims": meta, "third_party": third}


class _Exposure:
    """Collects the numbers the paper modules' functions return to each other (what a statement
    compares), through ``sys.setprofile``, by function.

    A function memoised with the ledger's ``input_cache`` is recorded where its wrapper returns,
    so a cache hit (a claim evaluated after another that computed the same thing) records the
    same numbers as a cold call.
    """

    def __init__(self, prefix: str) -> None:
        self.prefix = prefix
        self.values: dict[str, list[float]] = defaultdict(list)
        self.n = 0

    def __call__(self, frame: Any, event: str, arg: Any) -> None:
        if event != "return" or self.n >= 20000:
            return
        module = frame.f_globals.get("__name__", "")
        code = frame.f_code
        if module.startswith(self.prefix):
            name = code.co_qualname
        elif module == "navcore.claims.inputs" and code.co_name == "wrapper":
            fn = frame.f_locals.get("fn")
            name = getattr(fn, "__qualname__", "")
            if not getattr(fn, "__module__", "").startswith(self.prefix):
                return
        else:
            return
        back = frame.f_back
        if back is None or not back.f_globals.get("__name__", "").startswith(self.prefix):
            return
        if type(arg) is float or (hasattr(arg, "dtype") and getattr(arg, "shape", None) == ()):
            try:
                self.values[name].append(float(arg))
                self.n += 1
            except (TypeError, ValueError):
                pass


def _evaluate(claim: Any, exposure_prefix: str) -> dict[str, Any]:
    from navcore.claims.runs import _run

    t0 = time.perf_counter()
    expo = _Exposure(exposure_prefix) if (claim.is_statement and exposure_prefix) else None
    try:
        if expo is not None:
            sys.setprofile(expo)
        try:
            value, reads = _run(claim)
        finally:
            if expo is not None:
                sys.setprofile(None)
        out: dict[str, Any] = {
            "value": bool(value) if claim.is_statement else float(value),
            "error": None,
            "reads": {k: _canonical(v.value) for k, v in reads.items()},
        }
    except Exception as exc:
        out = {"value": None, "error": f"{type(exc).__name__}: {exc}", "reads": {}}
    out["exposures"] = dict(expo.values) if expo is not None else None
    out["seconds"] = time.perf_counter() - t0
    return out


def trace_claim(target: Target, claim_id: str) -> dict[str, Any]:
    """Run in a child forked from a process that imported the package: one claim, traced."""
    import coverage

    claims = _load_claims(target)
    claim = claims[claim_id][0]
    cov = coverage.Coverage(data_file=None, config_file=False, branch=False, include=[str(target.root / "*")])
    cov.start()
    try:
        out = _evaluate(claim, target.exposure_prefix)
    finally:
        cov.stop()
    data = cov.get_data()
    lines: dict[str, list[int]] = {}
    for f in data.measured_files():
        p = Path(f)
        try:
            rel = str(p.relative_to(target.repo))
        except ValueError:
            rel = str(p)
        lines[rel] = sorted(data.lines(f) or ())
    out["lines"] = lines
    return out


def trace_all(
    target: Target, claim_ids: list[str], jobs: int, workdir: Path, nice: int, log: Callable[[str], None]
) -> dict[str, Any]:
    """Run in a child (the trace parent): import the package, then one forked child per claim."""
    importlib.import_module(target.package)
    _load_claims(target)  # imported, nothing evaluated
    import coverage  # noqa: F401  (imported once, before the forks)

    results: dict[str, Any] = {}
    sched = Scheduler(jobs, workdir, nice=nice, log=log)
    t0 = time.monotonic()

    def done(cid: str) -> Callable[[Any, str | None], None]:
        def cb(result: Any, error: str | None) -> None:
            results[cid] = (
                result
                if error is None
                else {
                    "value": None,
                    "error": error,
                    "reads": {},
                    "exposures": None,
                    "seconds": 0.0,
                    "lines": {},
                }
            )
            if len(results) % 25 == 0:
                log(f"  traced {len(results)}/{len(claim_ids)} claims ({time.monotonic() - t0:.0f} s)")

        return cb

    for cid in claim_ids:
        sched.submit(Task(cid, trace_claim, (target, cid), 900.0, done(cid)))
    sched.run()
    return results


class _Replace(ast.NodeTransformer):
    def __init__(self, spots: dict[tuple[int, int, int, int], int | float]) -> None:
        self.spots = spots
        self.found: set[tuple[int, int, int, int]] = set()

    def visit(self, node: ast.AST) -> Any:
        if hasattr(node, "lineno") and _literal_value(node) is not None:
            key = (node.lineno, node.col_offset, node.end_lineno, node.end_col_offset)  # type: ignore[attr-defined]
            if key in self.spots:
                self.found.add(key)
                return ast.copy_location(ast.Constant(self.spots[key]), node)
        return self.generic_visit(node)


class _PerturbedLoader(importlib.machinery.SourceFileLoader):
    spots: ClassVar[dict[str, dict[tuple[int, int, int, int], int | float]]] = {}

    def get_code(self, fullname: str) -> Any:
        source = importlib.util.decode_source(self.get_data(self.path))
        tree = ast.parse(source, self.path)
        rep = _Replace(self.spots[fullname])
        tree = rep.visit(tree)
        missing = set(self.spots[fullname]) - rep.found
        if missing:
            raise RuntimeError(f"input gate: literals not found in {fullname}: {sorted(missing)}")
        ast.fix_missing_locations(tree)
        return compile(tree, self.path, "exec", dont_inherit=True)


class _PerturbedFinder(importlib.abc.MetaPathFinder):
    def find_spec(self, fullname: str, path: Any, target: Any = None) -> Any:
        if fullname not in _PerturbedLoader.spots:
            return None
        spec = importlib.machinery.PathFinder.find_spec(fullname, path)
        if spec is None or spec.origin is None:
            return None
        spec.loader = _PerturbedLoader(fullname, spec.origin)
        return spec


def evaluate_perturbed(
    target: Target,
    spots: dict[str, dict[tuple[int, int, int, int], int | float]],
    claim_ids: list[str],
    modules: list[str],
    stop: Callable[[str, dict[str, Any]], bool] | None = None,
) -> dict[str, Any]:
    """Run in a child of the perturbation parent (which never imported the package): import the
    package with some literals rewritten, then the claim modules ``modules``, then evaluate the
    claims in order; with ``stop``, return as soon as ``stop(claim_id, result)`` is true (a group
    that moves one claim is split whatever the others do)."""
    _PerturbedLoader.spots = spots
    sys.meta_path.insert(0, _PerturbedFinder())
    importlib.invalidate_caches()
    importlib.import_module(target.package)
    claims: dict[str, Any] = {}
    for name in modules:
        for c in getattr(importlib.import_module(name), "CLAIMS", ()):
            claims[c.id] = c
    out: dict[str, Any] = {}
    for cid in claim_ids:
        out[cid] = _evaluate(claims[cid], target.exposure_prefix)
        if stop is not None and stop(cid, out[cid]):
            break
    return out


# ------------------------------------------------------------------------------------------
# Comparing a perturbed evaluation with the nominal one
# ------------------------------------------------------------------------------------------
@dataclass
class Effect:
    """How a perturbation changed one claim."""

    tolerances: float = 0.0  # |change| / tolerance (numeric claims)
    flipped: bool = False  # a statement's truth value changed
    exposure_rel: float = 0.0  # largest relative change of a statement's numbers
    error: str | None = None  # the perturbed evaluation raised
    inputs_changed: tuple[str, ...] = ()  # recorded inputs whose values differ

    def moved(self, tolerances: float, exposure_rel: float) -> bool:
        return (
            self.error is not None
            or self.flipped
            or self.tolerances > tolerances
            or (self.exposure_rel > exposure_rel)
        )


def compare(meta: dict[str, Any], nominal: dict[str, Any], perturbed: dict[str, Any]) -> Effect:
    """The effect of a perturbation on one claim (see :class:`Effect`)."""
    eff = Effect()
    if perturbed.get("error"):
        if nominal.get("error"):
            return eff
        eff.error = perturbed["error"]
        return eff
    changed = [
        k
        for k in set(nominal["reads"]) | set(perturbed["reads"])
        if nominal["reads"].get(k) != perturbed["reads"].get(k)
    ]
    eff.inputs_changed = tuple(sorted(changed))
    v0, v1 = nominal["value"], perturbed["value"]
    if meta["statement"]:
        eff.flipped = bool(v0) != bool(v1)
        e0, e1 = nominal.get("exposures") or {}, perturbed.get("exposures") or {}
        worst = 0.0
        for name in set(e0) & set(e1):
            if len(e0[name]) != len(e1[name]):
                continue  # called another number of times (a memo of another kind): not comparable
            for a, b in zip(e0[name], e1[name], strict=True):
                if a == b:
                    continue
                if not (math.isfinite(a) and math.isfinite(b)):
                    worst = max(worst, 1.0)
                    continue
                worst = max(worst, abs(b - a) / max(abs(a), abs(b), 1e-300))
        eff.exposure_rel = worst
        return eff
    if v0 is None or v1 is None:
        return eff
    if not (math.isfinite(v0) and math.isfinite(v1)):
        eff.tolerances = 0.0 if (v0 == v1 or (math.isnan(v0) and math.isnan(v1))) else math.inf
        return eff
    allowed = meta["allowed"]
    floor = EXACT_FLOOR_REL * max(abs(v0), abs(float(meta["published"])), 1e-300)
    scale = allowed if (allowed and math.isfinite(allowed) and allowed > floor) else floor
    eff.tolerances = abs(v1 - v0) / scale
    return eff


# ------------------------------------------------------------------------------------------
# Perturbation values
# ------------------------------------------------------------------------------------------
def perturbed_value(value: int | float, sign: int, magnitude: float = 1.0, rel: float = DELTA) -> int | float:
    """``value`` moved by ``sign * magnitude * rel`` relative (integers by a whole step at
    least; a float zero by ``ZERO_STEP * magnitude * rel / DELTA``, an integer zero by 1)."""
    if isinstance(value, int):
        moved = round(value * (1 + sign * magnitude * rel))
        return moved if moved != value else value + sign
    if value == 0:
        return sign * magnitude * ZERO_STEP * rel / DELTA
    return value * (1 + sign * magnitude * rel)


def _times(value: int | float, factor: float) -> int | float:
    """``value`` times ``factor`` (an integer stays an integer and moves by one at least)."""
    if isinstance(value, int):
        moved = round(value * factor)
        return moved if moved != value else value + (1 if factor > 1 else -1)
    return value * factor


def probe_size(value: int | float, moved: int | float) -> float:
    """The relative size of a perturbation; for a zero, which has no scale, SCALE itself (its
    probe's effect is judged as it is, not scaled)."""
    if value == 0:
        return SCALE
    return abs((moved - value) / value)


# ------------------------------------------------------------------------------------------
# The gate
# ------------------------------------------------------------------------------------------
@dataclass
class Finding:
    """What one candidate does to the claims, once tested alone."""

    candidate: Candidate
    effects: dict[str, dict[str, Any]] = field(default_factory=dict)  # claim -> worst effect
    status: str = "no-effect"


def _source_key(target: Target) -> str:
    h = hashlib.sha256(TOOL_VERSION.encode())
    for name in ("numpy", "scipy"):
        with contextlib.suppress(importlib.metadata.PackageNotFoundError):
            h.update(f"{name} {importlib.metadata.version(name)}".encode())
    for f in sorted(target.root.rglob("*.py")):
        h.update(str(f.relative_to(target.root)).encode())
        h.update(f.read_bytes())
    return h.hexdigest()[:20]


def _run_in_child(
    fn: Callable[..., Any],
    args: tuple[Any, ...],
    workdir: Path,
    nice: int,
    timeout: float = 7200.0,
    capture: bool = True,
) -> Any:
    box: dict[str, Any] = {}

    def cb(result: Any, error: str | None) -> None:
        box["result"], box["error"] = result, error

    sched = Scheduler(1, workdir, nice=nice)
    sched.submit(Task("child", fn, args, timeout, cb, capture))
    sched.run()
    if box.get("error"):
        raise RuntimeError(f"input gate: a child failed:\n{box['error']}")
    return box["result"]


class Gate:
    """One run of the gate over a selection of claims and modules."""

    def __init__(
        self,
        target: Target,
        *,
        papers: list[str] | None = None,
        claim_prefixes: list[str] | None = None,
        modules: list[str] | None = None,
        sample: int | None = None,
        seed: int = 0,
        jobs: int = 2,
        nice: int = 5,
        audit: bool = False,
        workdir: Path | None = None,
        use_cache: bool = True,
        max_seconds: float | None = None,
        log: Callable[[str], None] = print,
    ) -> None:
        self.target = target
        self.papers = papers or []
        self.claim_prefixes = claim_prefixes or []
        self.modules = modules or []
        self.sample = sample
        self.seed = seed
        self.jobs = jobs
        self.nice = nice
        self.audit = audit
        self.workdir = workdir or (ROOT / "_build" / "input_gate")
        self.use_cache = use_cache
        self.max_seconds = max_seconds
        self.slow: list[str] = []
        self.log = log
        self.children = 0
        self.child_seconds = 0.0

    # -- phases ----------------------------------------------------------------------------
    def _prepare(self) -> None:
        self.workdir.mkdir(parents=True, exist_ok=True)
        for old in self.workdir.glob("task-*"):
            old.unlink(missing_ok=True)
        key = _source_key(self.target)
        self.cache_file = self.workdir / f"trace-{self.target.package}-{key}.json"
        cached: dict[str, Any] = {}
        if self.use_cache and self.cache_file.exists():
            with contextlib.suppress(ValueError, OSError):
                cached = json.loads(self.cache_file.read_text())
        if "meta" in cached:
            self.meta = cached["meta"]
        else:
            self.log("reading the claims (a child imports the package)")
            self.meta = _run_in_child(claims_metadata, (self.target,), self.workdir, self.nice)
            cached = {"meta": self.meta, "traces": {}}
        self.cached = cached
        claims = self.meta["claims"]
        selected = [cid for cid, m in claims.items() if m["computes"]]
        if self.papers:
            selected = [c for c in selected if claims[c]["paper"] in self.papers]
        if self.claim_prefixes:
            selected = [c for c in selected if any(c.startswith(p) for p in self.claim_prefixes)]
        if self.sample is not None and self.sample < len(selected):
            rng = random.Random(self.seed)
            selected = sorted(rng.sample(selected, self.sample), key=list(claims).index)
        self.selected = selected

    def _trace(self) -> None:
        traces: dict[str, Any] = self.cached.setdefault("traces", {})
        missing = [c for c in self.selected if c not in traces]
        if missing:
            self.log(f"tracing {len(missing)} claims, each from cold caches ({self.jobs} at a time)")
            t0 = time.monotonic()
            new = _run_in_child(
                trace_all,
                (self.target, missing, self.jobs, self.workdir, self.nice, self.log),
                self.workdir,
                0,
                timeout=6 * 3600.0,
                capture=False,
            )
            traces.update(new)
            self.trace_seconds = time.monotonic() - t0
            if self.use_cache:
                tmp = self.cache_file.with_suffix(".tmp")
                tmp.write_text(json.dumps(self.cached))
                os.replace(tmp, self.cache_file)
        else:
            self.trace_seconds = 0.0
        if self.max_seconds is not None:
            self.slow = [c for c in self.selected if traces[c].get("seconds", 0.0) > self.max_seconds]
            self.selected = [c for c in self.selected if c not in self.slow]
        self.traces = {c: traces[c] for c in self.selected}

    def _preload(self) -> None:
        """Import the third-party modules the package uses, but not the package itself."""
        pkg = self.target.package
        if pkg in sys.modules or any(m.startswith(pkg + ".") for m in sys.modules):
            if pkg == "navcore":
                raise RuntimeError("input gate: the perturbation parent must not import navcore")
        for name in self.meta["third_party"]:
            if name in sys.modules:
                continue
            with contextlib.suppress(Exception):
                importlib.import_module(name)

    def _candidates(self) -> None:
        index = index_package(self.target)
        self.index = index
        cands = index.candidates
        if self.modules:
            cands = [c for c in cands if any(m in c.module or m in c.file for m in self.modules)]
        self.all_candidates = cands
        self.rel = relevance(index, self.traces, cands)
        self.tested = [
            c for c in cands if self.rel.claims_of[c.id] and (self.audit or (not c.rule and c.allow is None))
        ]

    def _control(self) -> None:
        """One child evaluates every selected claim in a row, unperturbed: a claim whose value
        differs from its lone, cold evaluation depends on what ran before it (reported)."""
        ok = [c for c in self.selected if not self.traces[c].get("error")]
        self.log(f"control: {len(ok)} claims in one process, unperturbed")
        res = _run_in_child(
            evaluate_perturbed, (self.target, {}, ok, self._modules(ok)), self.workdir, self.nice
        )
        self.unstable: dict[str, str] = {}
        for cid in ok:
            eff = compare(self.meta["claims"][cid], self.traces[cid], res[cid])
            if eff.moved(0.0, 0.0) or eff.inputs_changed:
                if eff.error:
                    why = eff.error
                elif self.meta["claims"][cid]["statement"]:
                    why = f"flipped: {eff.flipped}; its numbers move by {eff.exposure_rel:.3g} (relative)"
                else:
                    why = f"moves by {eff.tolerances:.3g} tolerances; inputs {list(eff.inputs_changed)}"
                self.unstable[cid] = why

    def _modules(self, claims: list[str]) -> list[str]:
        """The claim modules that define ``claims``, in registry order."""
        wanted = {self.meta["claims"][c]["module"] for c in claims}
        return [m for m in dict.fromkeys(m["module"] for m in self.meta["claims"].values()) if m in wanted]

    def _perturb(self) -> None:
        rng = random.Random(self.seed + 1)
        self.findings: dict[str, Finding] = {c.id: Finding(c) for c in self.tested}
        self.group_log: list[dict[str, Any]] = []
        sched = Scheduler(self.jobs, self.workdir, nice=self.nice, log=self.log)
        self.sched = sched
        nominal = self.traces
        claim_meta = self.meta["claims"]
        order = {cid: i for i, cid in enumerate(self.selected)}
        t0 = time.monotonic()

        def claims_for(
            cands: list[Candidate], within: set[str] | None = None, statements: bool = False
        ) -> list[str]:
            s: set[str] = set()
            for c in cands:
                s |= self.rel.claims_of[c.id]
            s = {x for x in s if x in nominal and not nominal[x].get("error") and x not in self.unstable}
            if within is not None:
                s &= within
            if statements:
                s = {x for x in s if claim_meta[x]["statement"]}
            return sorted(s, key=order.__getitem__)

        def cheap_first(claims: list[str]) -> list[str]:
            """The quickest claims first: a group that moves one stops there."""
            return sorted(claims, key=lambda c: (nominal[c]["seconds"], order[c]))

        def stop_probe(cid: str, result: dict[str, Any]) -> bool:
            return compare(claim_meta[cid], nominal[cid], result).moved(GROUP_TOLERANCES, STATEMENT_GROUP_REL)

        def stop_flip(cid: str, result: dict[str, Any]) -> bool:
            eff = compare(claim_meta[cid], nominal[cid], result)
            return eff.flipped or eff.error is not None

        def timeout(claims: list[str]) -> float:
            return 120.0 + 6.0 * sum(nominal[c]["seconds"] for c in claims)

        def spots(
            assign: list[tuple[Candidate, int | float]],
        ) -> dict[str, dict[tuple[int, int, int, int], Any]]:
            out: dict[str, dict[tuple[int, int, int, int], Any]] = defaultdict(dict)
            for c, v in assign:
                out[c.module][c.position] = v
            return dict(out)

        def submit_group(cands: list[Candidate], claims: list[str], depth: int) -> None:
            if not claims:
                return
            if len(cands) == 1:
                submit_single(cands[0], claims, +1)
                return
            assign = [
                (c, perturbed_value(c.value, rng.choice((-1, 1)), rng.uniform(0.5, 1.0))) for c in cands
            ]

            def cb(result: Any, error: str | None) -> None:
                self.children += 1
                moved: set[str] = set()
                if error is not None:  # the whole group broke: split to find out which
                    moved = set(claims)
                else:
                    for cid in claims:
                        if cid not in result:  # not evaluated: the group stopped at a move
                            moved.add(cid)
                            continue
                        self.child_seconds += result[cid]["seconds"]
                        eff = compare(claim_meta[cid], nominal[cid], result[cid])
                        if eff.moved(GROUP_TOLERANCES, STATEMENT_GROUP_REL):
                            moved.add(cid)
                self.group_log.append(
                    {
                        "size": len(cands),
                        "claims": len(claims),
                        "moved": len(moved),
                        "depth": depth,
                        "error": error is not None,
                    }
                )
                self._progress(t0)
                if not moved:
                    return
                half = len(cands) // 2
                for part in (cands[:half], cands[half:]):
                    submit_group(part, claims_for(part, moved), depth + 1)

            sched.submit(
                Task(
                    f"group-{len(cands)}",
                    evaluate_perturbed,
                    (self.target, spots(assign), cheap_first(claims), self._modules(claims), stop_probe),
                    timeout(claims),
                    cb,
                )
            )

        def submit_scale_group(cands: list[Candidate], claims: list[str], depth: int) -> None:
            """Statements are judged at +-SCALE: does the group flip one? Each literal is tried at
            both signs (two children with opposite sign patterns)."""
            if not claims:
                return
            if len(cands) == 1:
                for sign in (+1, -1):
                    submit_single(cands[0], claims, sign, "scale")
                return
            pattern = [(c, rng.choice((-1, 1)), rng.uniform(0.5, 1.0)) for c in cands]
            join: dict[str, Any] = {"pending": 2, "moved": set()}

            def cb(result: Any, error: str | None) -> None:
                self.children += 1
                if error is not None:
                    join["moved"] |= set(claims)
                else:
                    for cid in claims:
                        if cid not in result:  # not evaluated: the group stopped at a flip
                            join["moved"].add(cid)
                            continue
                        self.child_seconds += result[cid]["seconds"]
                        eff = compare(claim_meta[cid], nominal[cid], result[cid])
                        if eff.flipped or eff.error is not None:
                            join["moved"].add(cid)
                join["pending"] -= 1
                self._progress(t0)
                if join["pending"] or not join["moved"]:
                    return
                half = len(cands) // 2
                for part in (cands[:half], cands[half:]):
                    submit_scale_group(part, claims_for(part, join["moved"], statements=True), depth + 1)

            for flip in (+1, -1):
                assign = [(c, perturbed_value(c.value, flip * sg, m, rel=SCALE)) for c, sg, m in pattern]
                sched.submit(
                    Task(
                        f"scale-group-{len(cands)}",
                        evaluate_perturbed,
                        (self.target, spots(assign), cheap_first(claims), self._modules(claims), stop_flip),
                        timeout(claims),
                        cb,
                    )
                )

        def record(cand: Candidate, cid: str, eff: Effect, value: int | float, mode: str) -> None:
            finding = self.findings[cand.id]
            rec = finding.effects.setdefault(
                cid,
                {
                    "tolerances": 0.0,  # the probe's effect, in tolerances
                    "tolerances_per_scale": 0.0,  # linearised to a SCALE change of the literal
                    "flipped": False,  # the probe flips the statement
                    "flipped_at_scale": False,  # a SCALE change flips it
                    "statement_numbers_rel": 0.0,
                    "error": None,
                    "error_at_scale": None,
                    "tolerances_at_factor": 0.0,  # x FACTOR or / FACTOR (where tried)
                    "flipped_at_factor": False,
                    "error_at_factor": None,
                    "inputs_changed_at_factor": [],
                    "inputs_changed": [],
                    "perturbed_to": [],
                },
            )
            rec["perturbed_to"].append(value)
            if mode == "factor":
                rec["flipped_at_factor"] = rec["flipped_at_factor"] or eff.flipped
                rec["error_at_factor"] = rec["error_at_factor"] or eff.error
                rec["tolerances_at_factor"] = max(rec["tolerances_at_factor"], eff.tolerances)
                rec["inputs_changed_at_factor"] = sorted(
                    set(rec["inputs_changed_at_factor"]) | set(eff.inputs_changed)
                )
                return
            if mode == "scale":
                rec["flipped_at_scale"] = rec["flipped_at_scale"] or eff.flipped
                rec["error_at_scale"] = rec["error_at_scale"] or eff.error
                if eff.flipped:
                    rec["inputs_changed_at_scale"] = sorted(
                        set(rec.get("inputs_changed_at_scale", [])) | set(eff.inputs_changed)
                    )
                return
            rec["inputs_changed"] = sorted(set(rec["inputs_changed"]) | set(eff.inputs_changed))
            rec["error"] = rec["error"] or eff.error
            rec["flipped"] = rec["flipped"] or eff.flipped
            rec["statement_numbers_rel"] = max(rec["statement_numbers_rel"], eff.exposure_rel)
            rec["tolerances"] = max(rec["tolerances"], eff.tolerances)
            size = probe_size(cand.value, value)
            scaled = eff.tolerances * SCALE / size if size else eff.tolerances
            rec["tolerances_per_scale"] = max(rec["tolerances_per_scale"], scaled)

        def submit_single(cand: Candidate, claims: list[str], sign: int, mode: str = "probe") -> None:
            """One literal alone: ``probe`` (+-DELTA), ``scale`` (+-SCALE, statements) or ``factor``
            (x or / FACTOR)."""
            if mode == "factor":
                value = _times(cand.value, FACTOR if sign > 0 else 1 / FACTOR)
            else:
                value = perturbed_value(cand.value, sign, rel=SCALE if mode == "scale" else DELTA)

            def cb(result: Any, error: str | None) -> None:
                self.children += 1
                moved: list[str] = []
                for cid in claims:
                    if error is not None:
                        eff = Effect(error=error.strip().splitlines()[-1][:300])
                    else:
                        self.child_seconds += result[cid]["seconds"]
                        eff = compare(claim_meta[cid], nominal[cid], result[cid])
                    if eff.moved(GROUP_TOLERANCES, STATEMENT_GROUP_REL) and eff.error is None:
                        moved.append(cid)
                    record(cand, cid, eff, value, mode)
                self._progress(t0)
                if mode != "probe":
                    return
                effects = self.findings[cand.id].effects
                if sign == +1 and moved and not any(self._flags(c, effects[c]) for c in moved):
                    # moved, but not past the flag: the other side may move more (a response
                    # at a turning point); a literal already flagged needs no second run
                    submit_single(cand, moved, -1)
                    return
                after_probe(cand, claims)

            sched.submit(
                Task(
                    f"single-{cand.id}",
                    evaluate_perturbed,
                    (self.target, spots([(cand, value)]), claims, self._modules(claims)),
                    timeout(claims),
                    cb,
                )
            )

        def after_probe(cand: Candidate, claims: list[str]) -> None:
            effects = self.findings[cand.id].effects
            # statements whose numbers the probe moves: do they flip at +-SCALE? (a literal of a
            # paper module is tried at +-SCALE by the scale track already)
            if not cand.module.startswith(self.target.exposure_prefix or "\0"):
                stmts = [
                    c
                    for c in claims
                    if claim_meta[c]["statement"]
                    and c in effects
                    and not (effects[c]["flipped"] or effects[c]["error"])
                    and effects[c]["statement_numbers_rel"] > STATEMENT_REPORT_REL
                    and not effects[c].get("scale_tried")
                ]
                for c in stmts:
                    effects[c]["scale_tried"] = True
                if stmts:
                    submit_single(cand, stmts, +1, "scale")
                    submit_single(cand, stmts, -1, "scale")
            # a factor FACTOR either way, where the probe says it could reach the flag (and
            # nothing is flagged yet): the claims whose linearised effect reaches a tenth of it,
            # and the statements whose numbers move
            if cand.value == 0 or any(self._flags(c, e) for c, e in effects.items()):
                return
            size = max(probe_size(cand.value, v) for v in effects[next(iter(effects))]["perturbed_to"])
            wide = [
                c
                for c in claims
                if c in effects
                and not effects[c]["error"]
                and (
                    effects[c]["tolerances"] * (FACTOR - 1) / max(size, 1e-300) > FLAG_TOLERANCES / 10
                    or (
                        claim_meta[c]["statement"]
                        and effects[c]["statement_numbers_rel"] > STATEMENT_REPORT_REL
                    )
                )
            ]
            if wide:
                submit_single(cand, wide, +1, "factor")
                submit_single(cand, wide, -1, "factor")

        by_module: dict[str, list[Candidate]] = defaultdict(list)
        for c in self.tested:
            by_module[c.module].append(c)
        modules = sorted(by_module, key=lambda m: -len(claims_for(by_module[m])))
        for module in modules:
            cands = sorted(by_module[module], key=lambda c: c.position)
            submit_group(cands, claims_for(cands), 0)
        self.log(f"perturbing {len(self.tested)} literals in {len(by_module)} modules")
        sched.run()
        # then the statements at +-SCALE: a statement's threshold lives in its paper module and
        # moves none of its numbers, so the paper modules' literals are tried at +-SCALE on the
        # statements (leaving out the literals whose probe already raised: a lookup key)
        broke = {cid for cid, f in self.findings.items() if any(e["error"] for e in f.effects.values())}
        for module in modules:
            if not module.startswith(self.target.exposure_prefix or "\0"):
                continue
            cands = sorted((c for c in by_module[module] if c.id not in broke), key=lambda c: c.position)
            submit_scale_group(cands, claims_for(cands, statements=True), 0)
        if sched.queue:
            self.log(f"trying the paper modules' literals at +-{100 * SCALE:g} % on the statements")
            sched.run()
        self.perturb_seconds = time.monotonic() - t0
        for f in self.findings.values():
            f.status = self._status(f)

    def _progress(self, t0: float) -> None:
        if self.children % 50 == 0:
            self.log(
                f"  {self.children} perturbed evaluations, {len(self.sched.queue)} queued "
                f"({time.monotonic() - t0:.0f} s)"
            )

    def _status(self, f: Finding) -> str:
        if any(self._flags(cid, e) for cid, e in f.effects.items()):
            if f.candidate.allow is not None:
                return "allowlisted"
            if f.candidate.rule:
                return "excused-by-rule"
            return "flagged"
        if any(e["error"] or e["error_at_scale"] for e in f.effects.values()):
            return "breaks"
        if any(
            self._moves(e) and (e["inputs_changed"] or e.get("inputs_changed_at_scale"))
            for e in f.effects.values()
        ):
            return "declared"
        if any(e["tolerances"] > 0 or e["statement_numbers_rel"] > 0 for e in f.effects.values()):
            return "below-threshold"
        return "no-effect"

    @staticmethod
    def _moves(e: dict[str, Any]) -> bool:
        """The literal moves this claim: beyond the threshold, or flips it."""
        return bool(
            e["flipped"]
            or e["flipped_at_scale"]
            or e["tolerances_per_scale"] > FLAG_TOLERANCES
            or e.get("flipped_at_factor")
            or e.get("tolerances_at_factor", 0.0) > FLAG_TOLERANCES
        )

    @staticmethod
    def _flags(cid: str, e: dict[str, Any]) -> bool:
        """Flagged: moves the claim while no recorded input changed and nothing raised."""
        if e["error"]:
            return False
        probe = not e["inputs_changed"] and (e["flipped"] or e["tolerances_per_scale"] > FLAG_TOLERANCES)
        scale = e["flipped_at_scale"] and not e.get("inputs_changed_at_scale")
        factor = (
            not e.get("error_at_factor")
            and not e.get("inputs_changed_at_factor")
            and (e.get("flipped_at_factor") or e.get("tolerances_at_factor", 0.0) > FLAG_TOLERANCES)
        )
        return bool(probe or scale or factor)

    # -- the run ---------------------------------------------------------------------------
    def run(self) -> dict[str, Any]:
        t_start = time.monotonic()
        self._prepare()
        self._trace()
        self._preload()
        self._candidates()
        self._control()
        if self.unstable:
            self.log(f"  {len(self.unstable)} claims depend on what ran before them (not tested)")
        self._perturb()
        self.total_seconds = time.monotonic() - t_start
        return self.report()

    # -- report ----------------------------------------------------------------------------
    def report(self) -> dict[str, Any]:
        meta = self.meta["claims"]
        rules = defaultdict(int)
        allowlisted = 0
        for c in self.all_candidates:
            if self.rel.claims_of[c.id]:
                if c.rule:
                    rules[c.rule] += 1
                elif c.allow is not None:
                    allowlisted += 1
        entries = []
        for f in self.findings.values():
            if f.status in ("no-effect",):
                continue
            c = f.candidate
            moved = {
                cid: e
                for cid, e in f.effects.items()
                if self._moves(e)
                or e["error"]
                or e["inputs_changed"]
                or e["statement_numbers_rel"] > STATEMENT_REPORT_REL
            }
            flagged_claims = sorted(cid for cid, e in f.effects.items() if self._flags(cid, e))
            worst = max(
                (e["tolerances_per_scale"] for cid, e in f.effects.items() if self._flags(cid, e)),
                default=0.0,
            )
            entries.append(
                {
                    "id": c.id,
                    "file": c.file,
                    "line": c.lineno,
                    "text": c.text,
                    "source": c.line_text,
                    "value": c.value,
                    "scope": c.scope,
                    "module": c.module,
                    "where": c.where,
                    "binding": c.binding,
                    "status": f.status,
                    "rule": c.rule,
                    "allowlist_reason": (c.allow or {}).get("reason", ""),
                    "classification": suggest_class(c, self.target),
                    "flagged_claims": flagged_claims,
                    "papers": sorted({meta[cid]["paper"] for cid in flagged_claims}),
                    "worst_tolerances": worst if math.isfinite(worst) else "inf",
                    "flips": sorted(
                        cid
                        for cid in flagged_claims
                        if f.effects[cid]["flipped"] or f.effects[cid]["flipped_at_scale"]
                    ),
                    "effects": {
                        cid: {
                            **{
                                k: (v if not (isinstance(v, float) and not math.isfinite(v)) else str(v))
                                for k, v in e.items()
                            },
                            "paper": meta[cid]["paper"],
                            "statement": meta[cid]["statement"],
                        }
                        for cid, e in sorted(moved.items())
                    },
                }
            )
        entries.sort(key=lambda e: (e["status"] != "flagged", e["file"], e["line"]))
        flagged = [e for e in entries if e["status"] == "flagged"]
        per_paper: dict[str, dict[str, int]] = defaultdict(lambda: {"numbers": 0, "claims": 0})
        claims_hit: dict[str, set[str]] = defaultdict(set)
        for e in flagged:
            for p in e["papers"]:
                per_paper[p]["numbers"] += 1
            for cid in e["flagged_claims"]:
                claims_hit[meta[cid]["paper"]].add(cid)
        for p, s in claims_hit.items():
            per_paper[p]["claims"] = len(s)
        return {
            "selection": {
                "papers": self.papers,
                "claims": self.claim_prefixes,
                "modules": self.modules,
                "sample": self.sample,
                "seed": self.seed,
                "audit": self.audit,
                "max_seconds": self.max_seconds,
                "left_out_as_slow": self.slow,
            },
            "settings": {
                "delta": DELTA,
                "zero_step": ZERO_STEP,
                "scale": SCALE,
                "factor": FACTOR,
                "flag_tolerances": FLAG_TOLERANCES,
                "group_tolerances": GROUP_TOLERANCES,
                "statement_group_rel": STATEMENT_GROUP_REL,
                "statement_report_rel": STATEMENT_REPORT_REL,
            },
            "counts": {
                "claims": len(self.selected),
                "claims_failing_nominally": sorted(c for c in self.selected if self.traces[c].get("error")),
                "claims_order_dependent": self.unstable,
                "literals": len(self.all_candidates),
                "literals_run_by_claims": sum(1 for c in self.all_candidates if self.rel.claims_of[c.id]),
                "excluded_by_rule": dict(sorted(rules.items())),
                "allowlisted": allowlisted,
                "perturbed": len(self.tested),
                "flagged": len(flagged),
                "by_status": dict(
                    sorted(
                        {
                            s: sum(1 for e in entries if e["status"] == s)
                            for s in {e["status"] for e in entries}
                        }.items()
                    )
                ),
                "per_paper": dict(sorted(per_paper.items())),
                "perturbed_evaluations": self.children,
                "seconds": {
                    "total": round(getattr(self, "total_seconds", 0.0), 1),
                    "trace": round(self.trace_seconds, 1),
                    "perturb": round(getattr(self, "perturb_seconds", 0.0), 1),
                },
            },
            "rules": RULES,
            "excluded_modules": self.target.exclude,
            "numbers": entries,
        }


def suggest_class(c: Candidate, target: Target) -> str:
    """A suggested classification of a flagged number (for whoever declares it)."""
    units = {0.3048, 1852.0, 1609.344, 299792458.0, 9.80665, 6378137.0, 3600.0, 60.0, 1000.0}
    if c.allow is not None:
        return c.allow.get("class", "exact/unit")
    if abs(float(c.value)) in units or c.module.endswith(".units"):
        return "exact/unit"
    paper = ".papers." in c.module or c.module.endswith(".papers")
    if paper:
        return "scenario value"
    if c.where in ("default", "class"):
        return "library default"
    if c.where == "module":
        return "modelling constant"
    return "rule of thumb / modelling constant"


def merge_reports(reports: list[dict[str, Any]]) -> dict[str, Any]:
    """One report from several runs on disjoint claim selections (a run per paper).

    A number found by several runs keeps every run's effects; its status is the strongest
    (flagged over breaks over declared over below-threshold).
    """
    rank = ["flagged", "allowlisted", "excused-by-rule", "breaks", "declared", "below-threshold", "no-effect"]
    numbers: dict[str, dict[str, Any]] = {}
    for rep in reports:
        for e in rep["numbers"]:
            prev = numbers.get(e["id"])
            if prev is None:
                numbers[e["id"]] = {**e, "effects": dict(e["effects"])}
                continue
            prev["effects"].update(e["effects"])
            prev["flagged_claims"] = sorted(set(prev["flagged_claims"]) | set(e["flagged_claims"]))
            prev["flips"] = sorted(set(prev["flips"]) | set(e["flips"]))
            prev["papers"] = sorted(set(prev["papers"]) | set(e["papers"]))
            prev["worst_tolerances"] = max(_num(prev["worst_tolerances"]), _num(e["worst_tolerances"]))
            if rank.index(e["status"]) < rank.index(prev["status"]):
                prev["status"] = e["status"]
    entries = sorted(numbers.values(), key=lambda e: (e["status"] != "flagged", e["file"], e["line"]))
    counts: dict[str, Any] = {
        k: 0 for k in ("claims", "literals_run_by_claims", "perturbed", "perturbed_evaluations")
    }
    counts["claims_failing_nominally"] = []
    counts["claims_order_dependent"] = {}
    counts["excluded_by_rule"] = defaultdict(int)
    counts["allowlisted"] = 0
    counts["seconds"] = {"total": 0.0, "trace": 0.0, "perturb": 0.0}
    for rep in reports:
        n = rep["counts"]
        for k in ("claims", "perturbed", "perturbed_evaluations", "allowlisted", "literals_run_by_claims"):
            counts[k] += n[k]
        counts["claims_failing_nominally"] += n["claims_failing_nominally"]
        counts["claims_order_dependent"].update(n["claims_order_dependent"])
        for k, v in n["excluded_by_rule"].items():
            counts["excluded_by_rule"][k] += v
        for k in counts["seconds"]:
            counts["seconds"][k] += n["seconds"][k]
    counts["excluded_by_rule"] = dict(sorted(counts["excluded_by_rule"].items()))
    counts["literals"] = reports[0]["counts"]["literals"] if reports else 0
    flagged = [e for e in entries if e["status"] == "flagged"]
    counts["flagged"] = len(flagged)
    statuses = sorted({e["status"] for e in entries})
    counts["by_status"] = {s: sum(1 for e in entries if e["status"] == s) for s in statuses}
    per_paper: dict[str, dict[str, int]] = defaultdict(lambda: {"numbers": 0, "claims": 0})
    hit: dict[str, set[str]] = defaultdict(set)
    for e in flagged:
        for p in e["papers"]:
            per_paper[p]["numbers"] += 1
        for cid in e["flagged_claims"]:
            hit[e["effects"][cid]["paper"]].add(cid)
    for p, claims in hit.items():
        per_paper[p]["claims"] = len(claims)
    counts["per_paper"] = dict(sorted(per_paper.items()))
    first = reports[0] if reports else {"settings": {}, "rules": RULES, "excluded_modules": {}}
    selection = {
        "papers": sorted({p for r in reports for p in r["selection"]["papers"]}),
        "claims": [],
        "modules": [],
        "sample": None,
        "seed": 0,
        "audit": any(r["selection"]["audit"] for r in reports),
        "merged_runs": len(reports),
    }
    return {
        "selection": selection,
        "settings": first["settings"],
        "counts": counts,
        "rules": first["rules"],
        "excluded_modules": first["excluded_modules"],
        "numbers": entries,
    }


def reapply_rules(report: dict[str, Any], index: Index) -> None:
    """Apply the current rules and allowlist to a stored report (runs made before a rule or an
    entry was added): a flagged number they now excuse becomes ``excused-by-rule`` or
    ``allowlisted``, as ``--audit`` would report it."""
    by_id = {c.id: c for c in index.candidates}
    for e in report["numbers"]:
        c = by_id.get(e["id"])
        if c is None or e["status"] != "flagged":
            continue
        if c.allow is not None:
            e["status"], e["allowlist_reason"] = "allowlisted", c.allow["reason"]
        elif c.rule:
            e["status"], e["rule"] = "excused-by-rule", c.rule
    flagged = [e for e in report["numbers"] if e["status"] == "flagged"]
    n = report["counts"]
    n["flagged"] = len(flagged)
    n["by_status"] = {
        s: sum(1 for e in report["numbers"] if e["status"] == s)
        for s in sorted({e["status"] for e in report["numbers"]})
    }
    per_paper: dict[str, dict[str, int]] = defaultdict(lambda: {"numbers": 0, "claims": 0})
    hit: dict[str, set[str]] = defaultdict(set)
    for e in flagged:
        for p in e["papers"]:
            per_paper[p]["numbers"] += 1
        for cid in e["flagged_claims"]:
            hit[e["effects"][cid]["paper"]].add(cid)
    for p, claims in hit.items():
        per_paper[p]["claims"] = len(claims)
    n["per_paper"] = dict(sorted(per_paper.items()))


def render_markdown(report: dict[str, Any]) -> str:
    """The report as Markdown: the summary, then every flagged number by paper and module."""
    out: list[str] = []
    n = report["counts"]
    scale = report["settings"]["scale"]
    out.append("# Input gate: numbers that move claims without being declared inputs\n")
    sel = report["selection"]
    out.append(
        f"Selection: papers {sel['papers'] or 'all'}, claims {sel['claims'] or 'all'}, modules "
        f"{sel['modules'] or 'all'}, sample {sel['sample'] or 'none'} (seed {sel['seed']})"
        f"{', audit' if sel['audit'] else ''}.\n"
    )
    if sel.get("left_out_as_slow"):
        out.append(
            f"Left out as slower than {sel['max_seconds']:g} s: {len(sel['left_out_as_slow'])} claims "
            f"({', '.join(sel['left_out_as_slow'])}).\n"
        )
    st = report["settings"]
    fac = st.get("factor", 10)
    out.append(
        f"A number is flagged when a change of it by {100 * scale:g} % (linearised from a probe of "
        f"±{100 * st['delta']:g} %), or by a factor {fac:g} either way, moves a claim by more than "
        f"{st['flag_tolerances']:g} of its tolerance, or when the probe, a ±{100 * scale:g} % change or a "
        f"factor {fac:g} flips a statement, while none of the inputs the claim records changes. Effects are "
        f"in tolerances per {100 * scale:g} % change of the number, else at ×/÷{fac:g}.\n"
    )
    out.append("## Summary\n")
    out.append(f"- claims: {n['claims']} ({len(n['claims_failing_nominally'])} fail at their nominal inputs)")
    order_dependent = n["claims_order_dependent"]
    out.append(f"- claims whose value depends on what ran before them (not tested): {len(order_dependent)}")
    for cid, why in n["claims_order_dependent"].items():
        out.append(f"  - `{cid}`: {why}")
    run_by = n["literals_run_by_claims"]
    out.append(f"- numeric literals in scope: {n['literals']}; run by the selected claims: {run_by}")
    rules = n["excluded_by_rule"]
    out.append(
        f"- excluded by rule: {sum(rules.values())} ({', '.join(f'{k} {v}' for k, v in rules.items())})"
    )
    out.append(f"- allowlisted (exact constants, unit definitions): {n['allowlisted']}")
    out.append(f"- perturbed: {n['perturbed']} in {n['perturbed_evaluations']} perturbed evaluations")
    out.append(f"- by outcome: {', '.join(f'{k} {v}' for k, v in n['by_status'].items())}")
    out.append(f"- **flagged: {n['flagged']}**")
    for p, s in n["per_paper"].items():
        out.append(f"  - {p}: {s['numbers']} numbers moving {s['claims']} claims")
    secs = n["seconds"]
    out.append(
        f"- time: {secs['total']:.0f} s (trace {secs['trace']:.0f} s, perturbation {secs['perturb']:.0f} s)\n"
    )
    flagged = [e for e in report["numbers"] if e["status"] == "flagged"]
    by_paper: dict[str, dict[str, list[dict[str, Any]]]] = defaultdict(lambda: defaultdict(list))
    for e in flagged:
        for p in e["papers"]:
            by_paper[p][e["file"]].append(e)
    for paper in sorted(by_paper):
        out.append(f"## {paper}\n")
        for file in sorted(by_paper[paper]):
            out.append(f"### `{file}`\n")
            head = f"moves (tolerances per {100 * scale:g} %)"
            out.append(f"| line | number | in | bound to | {head} | suggested class |")
            out.append("| --- | --- | --- | --- | --- | --- |")
            for e in sorted(by_paper[paper][file], key=lambda e: e["line"]):
                mine = [cid for cid in e["flagged_claims"] if e["effects"][cid]["paper"] == paper]
                shown = []

                def weight(c: str, e: dict[str, Any] = e) -> float:
                    x = e["effects"][c]
                    return _num(x["tolerances_per_scale"]) + 1e-3 * _num(x.get("tolerances_at_factor", 0.0))

                for cid in sorted(mine, key=lambda c: -weight(c))[:8]:
                    eff = e["effects"][cid]
                    factor = report["settings"].get("factor", 10)
                    if eff["flipped"]:
                        how = "flips"
                    elif eff["flipped_at_scale"]:
                        how = f"flips at ±{100 * scale:g} %"
                    elif _num(eff["tolerances_per_scale"]) > report["settings"]["flag_tolerances"]:
                        how = f"{_num(eff['tolerances_per_scale']):.3g}"
                    elif eff.get("flipped_at_factor"):
                        how = f"flips at ×/÷{factor:g}"
                    else:
                        how = f"{_num(eff.get('tolerances_at_factor', 0.0)):.3g} at ×/÷{factor:g}"
                    shown.append(f"`{cid}` {how}")
                more = f" and {len(mine) - 8} more" if len(mine) > 8 else ""
                out.append(
                    f"| {e['line']} | `{e['text']}` | `{e['scope']}` | {e['binding'] or ''} | "
                    f"{len(mine)} claims: {', '.join(shown)}{more} | {e['classification']} |"
                )
            out.append("")
    others = [e for e in report["numbers"] if e["status"] != "flagged"]
    if others:
        out.append("## Other outcomes\n")
        out.append(
            "Numbers that move claims but are not flagged: they feed a declared input (`declared`), "
            "move less than the threshold (`below-threshold`), make the computation fail when "
            "perturbed (`breaks`), or are excused (`allowlisted`, `excused-by-rule`, with `--audit`).\n"
        )
        out.append("| status | file:line | number | in | detail |")
        out.append("| --- | --- | --- | --- | --- |")
        for e in others:
            detail = ""
            effs = e["effects"]
            if e["status"] == "declared":
                inputs = sorted({i for x in effs.values() for i in x["inputs_changed"]})
                detail = "feeds " + ", ".join(f"`{i}`" for i in inputs[:4])
            elif e["status"] == "breaks":
                errs = sorted({x["error"] for x in effs.values() if x["error"]})
                detail = (errs[0] if errs else "")[:120].replace("|", "\\|")
            elif e["status"] in ("allowlisted", "excused-by-rule"):
                detail = e["allowlist_reason"] or e["rule"]
            else:
                worst = max((_num(x["tolerances_per_scale"]) for x in effs.values()), default=0.0)
                sn = max((x["statement_numbers_rel"] for x in effs.values()), default=0.0)
                detail = f"worst {worst:.2g} tolerances per {100 * scale:g} %" + (
                    f"; a statement's numbers {sn:.2g} (relative) per probe" if sn else ""
                )
            out.append(
                f"| {e['status']} | {e['file']}:{e['line']} | `{e['text']}` | `{e['scope']}` | {detail} |"
            )
        out.append("")
    return "\n".join(out) + "\n"


def _num(x: Any) -> float:
    return math.inf if x == "inf" else float(x)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--paper", action="append", default=[], help="only this paper's claims (repeatable)")
    parser.add_argument("--claim", action="append", default=[], help="only claims whose id starts with this")
    parser.add_argument("--module", action="append", default=[], help="only numbers in modules matching this")
    parser.add_argument("--sample", type=int, default=None, help="N claims drawn at random (seeded)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--nice", type=int, default=5, help="niceness of the children (default 5)")
    parser.add_argument("--audit", action="store_true", help="also perturb excluded and allowlisted numbers")
    parser.add_argument(
        "--max-seconds",
        type=float,
        default=None,
        help="leave out claims whose nominal evaluation takes longer (a quick sample)",
    )
    parser.add_argument("--no-cache", action="store_true", help="trace again even if a trace is stored")
    parser.add_argument("--out", type=Path, default=ROOT / "_build", help="folder of input_gate.json/.md")
    parser.add_argument(
        "--workdir",
        type=Path,
        default=ROOT / "_build" / "input_gate",
        help="the trace cache and the children's files",
    )
    parser.add_argument(
        "--merge",
        nargs="+",
        type=Path,
        default=None,
        help="combine the input_gate.json of several runs (one per paper) into --out; runs nothing",
    )
    args = parser.parse_args(argv)
    if args.merge:
        report = merge_reports([json.loads(p.read_text()) for p in args.merge])
        reapply_rules(report, index_package(navcore_target()))
        args.out.mkdir(parents=True, exist_ok=True)
        (args.out / "input_gate.json").write_text(json.dumps(report, indent=1) + "\n")
        (args.out / "input_gate.md").write_text(render_markdown(report))
        print(f"input gate: {report['counts']['flagged']} flagged numbers in {len(args.merge)} runs")
        return 1 if report["counts"]["flagged"] else 0
    # stop cleanly (every child with it) on Ctrl-C or SIGTERM, also when started in the background
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.signal(signal.SIGTERM, _exit_on_signal)
    for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ.setdefault(var, "1")
    os.environ["NAVCORE_CACHE"] = "off"
    os.environ["NAVCORE_NO_DISK_CACHE"] = "1"
    os.environ.setdefault("MPLBACKEND", "Agg")
    gate = Gate(
        navcore_target(),
        papers=args.paper,
        claim_prefixes=args.claim,
        modules=args.module,
        sample=args.sample,
        seed=args.seed,
        jobs=args.jobs,
        nice=args.nice,
        audit=args.audit,
        workdir=args.workdir,
        use_cache=not args.no_cache,
        max_seconds=args.max_seconds,
        log=lambda s: print(s, flush=True),
    )
    report = gate.run()
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "input_gate.json").write_text(json.dumps(report, indent=1, sort_keys=False) + "\n")
    (args.out / "input_gate.md").write_text(render_markdown(report))
    n = report["counts"]
    print(
        f"input gate: {n['flagged']} flagged numbers; {n['perturbed']} perturbed; "
        f"report in {args.out / 'input_gate.md'}"
    )
    return 1 if n["flagged"] else 0


if __name__ == "__main__":
    sys.exit(main())
