"""Every number a page glues is a claim's value or registered in navcore.glued (issue 31, item 2).

The pages print computed numbers by gluing them (``glue(name, value)``) and quoting them with
``{glue:text}`` roles. A page runs only in the book build, whose gates check form, not values;
so this test reads the pages' code cells (Python's ``ast``, no execution) and holds each glue
call to one of:

- **a claim's value**: the glued expression reads a ledger claim, by its id (a string literal
  that is a claim id) or through a claim's evaluation or record (the attributes ``reproduced``,
  ``published`` or ``band``); the claim tests recompute it against its tolerance (a count of
  verdicts, ``status``, is not a claim's value);
- **registered**: the glue name (or, for an f-string name, its pattern) is registered in
  :mod:`navcore.glued` for that page, with the function computing it, which
  ``tests/test_glue_values.py`` checks against an independent oracle and which
  :func:`navcore.book.glue` compares with what the page glues;
- **a declared input**: the glued expression is one of the ledger's declared inputs read
  through its paper module's ``IN`` (``float(sp.IN.cruise_altitude_m / 1000.0)``: the input
  itself, at most converted by a number or negated); its value, provenance and reason are in
  the ledger, and an oracle would only read the same declaration twice;
- **a ledger count**: the glued expression counts what the ledger itself returns, calling
  ``ledger.counts``, ``ledger.evaluations`` or ``ledger.errata`` (how many claims a paper has,
  how many are reproduced, how many errata): the ledger page reads the same functions, each
  claim's verdict is pinned by its expected status in the claim tests and the errata by their
  registry's tests, so a re-implementation of the count would only repeat them;
- **a setting**: the glued expression is a simulation setting (a seed, a number of draws or
  trials) that the page itself assigns from a number literal (``seed, draws = 20260101,
  400_000``), or that a navcore module (a paper or a model) assigns so at its top level and
  the page reads by its upper-case name (``mc.WINDOW_TRIALS``, or one point
  ``mc.WINDOW_PF[0]`` of a grid of number literals), at most converted by ``int``, ``float``
  or ``str`` or
  formatted (``f"{draws:,}"``, a ``.replace`` of that text). Nothing computes it: it is the
  book's choice, printed so that a reader can repeat the run, and an oracle would only read the
  same literal twice;
- **a figure**: the glued object is a figure (``fig``), not a number;

Anything else fails: a new glued number must come with its registration and oracle, or read a
claim.
"""

from __future__ import annotations

import ast
import re
import sys
from functools import cache
from pathlib import Path

import pytest

from navcore import glued

ROOT = Path(__file__).resolve().parents[1]
BOOK = ROOT / "book"

_CELL = re.compile(r"^```\{code-cell\}[^\n]*\n(.*?)^```", re.S | re.M)
_CLAIM_ATTRIBUTES = {"reproduced", "published", "band"}


@cache
def _claim_ids() -> frozenset[str]:
    from navcore.ledger import claims

    return frozenset(c.id for c in claims())


def _name_pattern(node: ast.expr) -> str | None:
    """A glue name as a page writes it: the literal, or an f-string's pattern with ``{field}``."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr):
        out = []
        for part in node.values:
            if isinstance(part, ast.Constant):
                out.append(str(part.value))
            elif isinstance(part, ast.FormattedValue):
                out.append("{" + ast.unparse(part.value) + "}")
        return "".join(out)
    return None


def _cell_source(src: str) -> str:
    """A code cell's Python: MyST cell options (``:tags:``, a ``---`` block) and magics dropped."""
    lines = src.splitlines()
    if lines and lines[0].strip() == "---":
        end = next(i for i in range(1, len(lines)) if lines[i].strip() == "---")
        lines = lines[end + 1 :]
    return "\n".join(line for line in lines if not line.startswith((":", "%")))


def _is_number(node: ast.expr) -> bool:
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        node = node.operand
    return (
        isinstance(node, ast.Constant)
        and isinstance(node.value, int | float)
        and not isinstance(node.value, bool)
    )


def _literal_assignments(tree: ast.AST) -> tuple[set[str], set[str]]:
    """Names a tree assigns from a number literal (``n = 24``, ``seed, draws = 1, 2``), and
    names it assigns otherwise."""
    literal, other = set(), set()
    for node in ast.walk(tree):
        targets: list[tuple[ast.expr, ast.expr | None]] = []
        if isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Tuple) and isinstance(node.value, ast.Tuple):
                    targets += list(zip(target.elts, node.value.elts, strict=False))
                else:
                    targets.append((target, node.value))
        elif isinstance(node, ast.AnnAssign | ast.AugAssign):
            targets.append((node.target, None))
        elif isinstance(node, ast.For | ast.comprehension):
            targets.append((node.target, None))
        for target, value in targets:
            for name in ast.walk(target):
                if isinstance(name, ast.Name):
                    is_lit = isinstance(target, ast.Name) and value is not None and _is_number(value)
                    (literal if is_lit else other).add(name.id)
    return literal, other


@cache
def page_settings(page: str) -> frozenset[str]:
    """Names a page's code cells assign once from a number literal and never otherwise."""
    literal, other = set(), set()
    text = (BOOK / f"{page}.md").read_text(encoding="utf-8")
    for m in _CELL.finditer(text):
        lit, oth = _literal_assignments(ast.parse(_cell_source(m.group(1))))
        literal |= lit
        other |= oth
    return frozenset(literal - other)


@cache
def _module_settings(module: str) -> frozenset[str]:
    """Upper-case names a navcore module (dotted name) assigns at its top level from a number literal."""
    path = ROOT.joinpath(*module.split(".")).with_suffix(".py")
    if not path.exists():
        return frozenset()
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out = set()
    for node in tree.body:
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
            if node.targets[0].id.isupper() and (_is_number(node.value) or _is_number_list(node.value)):
                out.add(node.targets[0].id)
    return frozenset(out)


def _is_number_list(node: ast.expr) -> bool:
    """A tuple or list of number literals, or ``np.array`` of one (a grid of settings)."""
    if isinstance(node, ast.Call) and ast.unparse(node.func) in ("np.array", "numpy.array"):
        node = node.args[0] if len(node.args) == 1 and not node.keywords else node
    return (
        isinstance(node, ast.Tuple | ast.List) and bool(node.elts) and all(_is_number(e) for e in node.elts)
    )


@cache
def _paper_aliases(page: str) -> dict[str, str]:
    """The page's aliases of navcore modules (``from navcore.detection import x as mc``), each
    to its dotted name: a paper module or a model module whose settings a page glues."""
    out = {}
    text = (BOOK / f"{page}.md").read_text(encoding="utf-8")
    for m in _CELL.finditer(text):
        for node in ast.walk(ast.parse(_cell_source(m.group(1)))):
            if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("navcore."):
                for alias in node.names:
                    out[alias.asname or alias.name] = f"{node.module}.{alias.name}"
    return out


def _reads_setting(page: str, value: ast.expr | None) -> bool:
    """Whether the glued expression is a setting: a name the page assigns from a number literal,
    or an upper-case number constant of a paper module read through the page's alias, at most
    converted (``int``, ``float``, ``str``), formatted in an f-string, or ``.replace``d."""
    node = value
    while node is not None:
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Name)
            and node.func.id in ("float", "int", "str")
        ):
            node = node.args[0] if len(node.args) == 1 and not node.keywords else None
        elif (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr == "replace"
            and all(isinstance(a, ast.Constant) for a in node.args)
        ):
            node = node.func.value
        elif (
            isinstance(node, ast.JoinedStr)
            and len(node.values) == 1
            and isinstance(node.values[0], ast.FormattedValue)
        ):
            node = node.values[0].value
        elif (
            isinstance(node, ast.Subscript)
            and isinstance(node.slice, ast.Constant)
            and isinstance(node.slice.value, int)
            and isinstance(node.value, ast.Attribute)
        ):
            node = node.value  # one point of a paper module's grid of settings
        else:
            break
    if isinstance(node, ast.Name):
        return node.id in page_settings(page)
    if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
        module = _paper_aliases(page).get(node.value.id)
        return module is not None and node.attr in _module_settings(module)
    return False


@cache
def glue_calls() -> tuple[tuple[str, str, str, ast.expr | None], ...]:
    """Every glue call of the book's pages: (page, name pattern, how glue was reached, value)."""
    out = []
    for path in sorted(BOOK.rglob("*.md")):
        if "_build" in path.parts:
            continue
        page = path.relative_to(BOOK).with_suffix("").as_posix()
        for m in _CELL.finditer(path.read_text(encoding="utf-8")):
            tree = ast.parse(_cell_source(m.group(1)), filename=str(path))
            for node in ast.walk(tree):
                if not isinstance(node, ast.Call):
                    continue
                func = node.func
                called = func.id if isinstance(func, ast.Name) else getattr(func, "attr", None)
                if called != "glue" or not node.args:
                    continue
                name = _name_pattern(node.args[0])
                assert name is not None, (
                    f"{page}: a glue name must be a string or an f-string: {ast.unparse(node)}"
                )
                value = node.args[1] if len(node.args) > 1 else None
                out.append((page, name, ast.unparse(func), value))
    return tuple(out)


def _reads_claim(value: ast.expr | None) -> bool:
    if value is None:
        return False
    ids = _claim_ids()
    for node in ast.walk(value):
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and node.value in ids:
            return True
        if isinstance(node, ast.Attribute) and node.attr in _CLAIM_ATTRIBUTES:
            return True
    return False


@cache
def _input_names() -> frozenset[str]:
    """The short names of the ledger's declared inputs (``cruise_altitude_m``)."""
    from navcore.claims.inputs import all_inputs
    from navcore.ledger import claims

    claims()  # imports every paper module, which declares its inputs
    return frozenset(i.name.rsplit(".", 1)[-1] for i in all_inputs())


def _reads_input(value: ast.expr | None) -> bool:
    """Whether the glued expression is a declared input read through ``IN``, as it is or
    converted: ``float()``/``int()`` around it, a minus sign, or a product or quotient with a
    number (a unit conversion). Anything computed from it is not the input."""
    node = value
    while node is not None:
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Name)
            and node.func.id in ("float", "int")
        ):
            node = node.args[0] if len(node.args) == 1 and not node.keywords else None
        elif isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
            node = node.operand
        elif isinstance(node, ast.BinOp) and isinstance(node.op, ast.Mult | ast.Div):
            numbers = [
                isinstance(side, ast.Constant) and isinstance(side.value, int | float)
                for side in (node.left, node.right)
            ]
            if numbers == [False, True]:
                node = node.left
            elif numbers == [True, False] and isinstance(node.op, ast.Mult):
                node = node.right
            else:
                return False
        else:
            break
    if not isinstance(node, ast.Attribute) or node.attr not in _input_names():
        return False
    owner = node.value
    return (isinstance(owner, ast.Attribute) and owner.attr == "IN") or (
        isinstance(owner, ast.Name) and owner.id == "IN"
    )


_LEDGER_COUNTS = {"counts", "evaluations", "errata"}


def _counts_ledger(value: ast.expr | None) -> bool:
    """Whether the glued expression calls ``ledger.counts``, ``ledger.evaluations`` or
    ``ledger.errata`` itself (a count kept in a variable first is not seen as one)."""
    if value is None:
        return False
    return any(
        isinstance(node, ast.Call)
        and isinstance(node.func, ast.Attribute)
        and node.func.attr in _LEDGER_COUNTS
        and isinstance(node.func.value, ast.Name)
        and node.func.value.id == "ledger"
        for node in ast.walk(value)
    )


def _is_figure(value: ast.expr | None) -> bool:
    return isinstance(value, ast.Name) and value.id == "fig"


def _fields_blank(pattern: str) -> str:
    return re.sub(r"\{[^{}]*\}", "{}", pattern)


def _registration(page: str, name: str) -> glued.GluedValue | None:
    """The registration of a glue name (or f-string pattern) as a page writes it, if any."""
    if "{" in name:
        return next(
            (e for e in glued.entries().values() if _fields_blank(e.pattern) == _fields_blank(name)),
            None,
        )
    found = glued.lookup(name)
    return found[0] if found else None


def _kind(page: str, name: str, value: ast.expr | None) -> str:
    if _registration(page, name) is not None:
        return "registered"
    if _reads_claim(value):
        return "claim"
    if _reads_input(value):
        return "input"
    if _counts_ledger(value):
        return "count"
    if _reads_setting(page, value):
        return "setting"
    if _is_figure(value):
        return "figure"
    return "unchecked"


def test_the_scan_finds_the_glue_calls():
    """The scan is not empty and sees every kind the pages use (a scan that finds nothing passes
    anything), and a glued expression of none of them is unchecked (the pages have none left)."""
    calls = glue_calls()
    assert len(calls) > 300
    kinds = {_kind(p, n, v) for p, n, _, v in calls}
    assert {"registered", "claim", "input", "count", "setting", "figure"} <= kinds
    made_up = ast.parse("float(spm.initial_error_effect_pct(members) / 2)", mode="eval").body
    assert _kind("sp/21-missions", "sp21-not-registered", made_up) == "unchecked"


def test_every_glued_number_is_a_claim_or_registered():
    """A glued number that is neither a claim's value nor registered (nor an input, a ledger count,
    a setting or a figure) fails."""
    bad = sorted(
        f"{page}: {name} = {ast.unparse(value) if value is not None else '?'}"
        for page, name, _, value in glue_calls()
        if _kind(page, name, value) == "unchecked"
    )
    assert not bad, (
        "glued numbers that are neither a claim's value nor registered in navcore.glued (register "
        "each with its function and an oracle in tests/test_glue_values.py):\n" + "\n".join(bad)
    )


def test_every_registration_is_glued_on_its_page():
    """Each registered name is glued on the page its registration names (no stale entries)."""
    shown = {(page, _registration(page, name)) for page, name, _, _ in glue_calls()}
    missing = [
        f"{e.pattern} (registered for {e.page})" for e in glued.entries().values() if (e.page, e) not in shown
    ]
    assert not missing, "registered glue names no page glues: " + ", ".join(missing)


def test_registered_names_are_not_claims():
    """A registered name does not read a claim too: one home for each glued number."""
    both = [f"{p}: {n}" for p, n, _, v in glue_calls() if _registration(p, n) is not None and _reads_claim(v)]
    assert not both, both


def test_pages_glue_through_navcore_book():
    """Pages glue with navcore.book.glue, which refuses a registered value its function does not compute."""
    direct = sorted(
        {
            str(path.relative_to(BOOK))
            for path in BOOK.rglob("*.md")
            if "_build" not in path.parts and "from myst_nb import glue" in path.read_text(encoding="utf-8")
        }
    )
    assert not direct, "pages importing myst_nb's glue instead of navcore.book.glue: " + ", ".join(direct)


@pytest.mark.parametrize(
    "source, kind",
    [
        ('glue("x-1", float(ev["KZL-fig5-ins-position"].reproduced))', "claim"),
        ('glue("x-2", value("SP-fig2.1-omega0"))', "claim"),
        ('glue("x-3", float(ledger.evaluate_claim(cid).reproduced))', "claim"),
        ('glue("x-4", float(2 * np.pi))', "unchecked"),
        ('glue("x-6", sum(ledger.evaluate_claim(i).status == "reproduced" for i in ids))', "unchecked"),
        ('glue("x-5", fig, display=False)', "figure"),
        ('glue("x-7", float(spj.IN.cruise_alt_m / 1000.0))', "input"),
        ('glue("x-8", -spj.IN.jammer_gain_db)', "input"),
        ('glue("x-9", float(1 / (6 * pm.IN.psk_chips)))', "unchecked"),  # computed from an input
        ('glue("x-10", float(spj.IN.cruise_alt_m / h))', "unchecked"),  # divided by a variable
        ('glue("x-11", float(spj.IN.not_an_input))', "unchecked"),  # no such declaration
        ('glue("x-12", float(obj.cruise_alt_m))', "unchecked"),  # not read through IN
        ('glue("x-13", int(ledger.counts("KZL")["KZL"]["total"]))', "count"),
        ('glue("x-14", len(ledger.errata("KZL")))', "count"),
        (
            'glue("x-15", sum(e.status == "reproduced" for e in ledger.evaluations("SP", prefix="T")))',
            "count",
        ),
        ('glue("x-16", int(n["total"]))', "unchecked"),  # a count kept in a variable
        ('glue("x-17", len(other.errata("KZL")))', "unchecked"),  # not the ledger's
        ('glue("kzl00-schuler-min", 84.45)', "registered"),
        ('glue(f"atc10-erp-K{k}-{p_dl}", 1.0)', "registered"),
        ('glue(f"atc10-erp-quarter-K{k}-{p_dl}", 1.0)', "unchecked"),
    ],
)
def test_classification(source, kind):
    """The rules on hand-written calls: a claim read by id or evaluation, a figure, a registered
    name or pattern (and a pattern that merely shares a prefix is not registered), a declared
    input read through IN (converted by a number at most), a count the ledger's own functions
    return, and plain arithmetic, which is unchecked."""
    call = ast.parse(source).body[0].value
    assert isinstance(call, ast.Call)
    name = _name_pattern(call.args[0])
    assert name is not None
    page = "atc10/10-jamming-model" if "atc10" in name else "kzl/00-requirements"
    assert _kind(page, name, call.args[1]) == kind


def test_page_settings_are_assigned_once_from_a_literal():
    """A setting is a name the page assigns from a number literal and never otherwise: a name
    also incremented, looped over or assigned a computed value is not one."""
    src = "seed, draws = 20260101, 400_000\nn = 3\nn += 1\nm = f(2)\nfor k in range(3):\n    pass\n"
    src += "k = 4\nx = -2.5"
    literal, other = _literal_assignments(ast.parse(src))
    assert literal - other == {"seed", "draws", "x"}


@pytest.mark.parametrize(
    "source, kind",
    [
        ('glue("x-1", f"{draws:,}".replace(",", " "))', "setting"),
        ('glue("x-2", str(seed))', "setting"),
        ('glue("x-3", int(mc.WINDOW_TRIALS))', "setting"),
        ('glue("x-4", seed * 2)', "unchecked"),  # computed from a setting
        ('glue("x-5", f"{draws / 2:,}")', "unchecked"),
        ('glue("x-6", float(mc.WINDOW_PF[0]))', "setting"),  # one point of a grid of literals
        ('glue("x-10", mc.X_DB[0])', "unchecked"),  # a computed grid (np.arange)
        ('glue("x-11", mc.WINDOW_PF[i])', "unchecked"),  # a point chosen by a variable
        ('glue("x-12", seed[0])', "unchecked"),  # a page setting is a number, not a grid
        ('glue("x-7", mc.simulate_window_declarations().trials)', "unchecked"),
        ('glue("x-8", other.WINDOW_TRIALS)', "unchecked"),  # not a paper module the page imports
        ('glue("x-9", n)', "unchecked"),  # not a setting of the page
    ],
)
def test_setting_classification(source, kind, monkeypatch):
    """Settings on hand-written calls: the page's literal settings ``seed`` and ``draws``, and a
    paper module's upper-case number constant read through the page's alias ``mc``."""
    monkeypatch.setattr(sys.modules[__name__], "page_settings", lambda page: frozenset({"seed", "draws"}))
    monkeypatch.setattr(
        sys.modules[__name__], "_paper_aliases", lambda page: {"mc": "navcore.detection.jamming_monte_carlo"}
    )
    call = ast.parse(source).body[0].value
    assert isinstance(call, ast.Call)
    assert _kind("sp/03-residual-acceleration", "x", call.args[1]) == kind
