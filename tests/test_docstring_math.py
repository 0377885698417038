"""No formula left as plain text in the API reference (issue 32, item 7).

The Reference part of the book renders the docstrings of the public API: each module's
docstring, its public functions and classes (each module's ``__all__``, as
:mod:`tests.test_api_docs` enumerates them), the methods and properties of those classes, and
the ``#:`` comments of public module data. A formula there belongs in a ``:math:`` role or a
``.. math::`` block; written as program text (``P = F P F^T + Q``, ``sigma_0``, ``sqrt(3b)``,
``1e-6``) it reads as code. The scan takes the prose a reader sees and leaves out what is not
prose: ``literal`` spans, ``:math:`` and other roles (cross-references name objects),
single-backtick names, ``.. math::`` and other directive and ``::`` literal blocks, doctest
lines and their output, the name-and-type lines of the numpydoc sections that list names
(*Parameters*, *Returns*, *Attributes*, ...: a parameter named ``sigma_0`` is a name), and
URLs. What is left is searched for :data:`tests.test_plain_math.PATTERNS`.

The hits not yet fixed are listed in ``tests/docstring_math_todo.txt`` as ``object<TAB>kind<TAB>
text``. The test fails on a hit missing from that list and on a listed entry that no longer
occurs, so the list only shrinks.

A formula in a ``literal`` span reads as program text too (``tr{(F'F)^-1}``), but a literal
is also how a docstring quotes code (``x ** (1/3)``, ``tau_bar = 0``). A literal is therefore
counted as a formula when it holds one of the patterns and is not Python (it does not parse
as an expression or a statement); those are listed, by object and text, in
``tests/docstring_literal_math_todo.txt``, which may likewise only shrink.

Oracle: the prose extractor and the detector are checked on hand-written docstrings with and
without plain math; the API's docstrings are then scanned with them.
"""

from __future__ import annotations

import ast
import importlib
import inspect
import re
from pathlib import Path

import pytest

from tests.test_api_docs import PUBLIC, _modules
from tests.test_plain_math import PATTERNS

ROOT = Path(__file__).resolve().parents[1]
TODO = ROOT / "tests" / "docstring_math_todo.txt"
LITERAL_TODO = ROOT / "tests" / "docstring_literal_math_todo.txt"

#: numpydoc sections whose unindented lines are names and types, not prose.
_NAME_SECTIONS = {
    "Parameters",
    "Other Parameters",
    "Returns",
    "Yields",
    "Receives",
    "Attributes",
    "Raises",
    "Warns",
    "Warnings",
    "See Also",
    "Methods",
    "Modules",
    "Constants",
}
_DIRECTIVE = re.compile(r"^(\s*)\.\. ")
_ROLE = re.compile(r":[\w:+-]+:`[^`]*`")
_LITERAL = re.compile(r"``.+?``", re.S)
_BACKTICK_NAME = re.compile(r"`[^`\n]*`_{0,2}")
_STRONG = re.compile(r"\*\*(?=\S)(.+?)(?<=\S)\*\*")  # reST bold, not a power
#: Names of distributions and functions that are words, not symbols ("chi-square", "gamma
#: function", "beta distribution", GNSS's "delta-range").
_WORDS = re.compile(
    r"\bchi-squared?\b|(?i:\bdelta[- ]range\b)|\b(?:gamma|beta)(?= (?:functions?|distributions?|variates?)\b)"
)
_URL = re.compile(r"<?https?://\S+|\bdoi:\S+|\b10\.\d{4,}/\S+")


def _indent(line: str) -> int:
    return len(line) - len(line.lstrip())


def _drop_blocks(lines: list[str]) -> list[str]:
    """Lines without directive blocks (``.. math::``, ``.. code-block::``, comments), ``::``
    literal blocks and doctests (``>>>`` lines, their continuations and their output)."""
    out: list[str] = []
    i = 0
    while i < len(lines):
        line = lines[i]
        stripped = line.strip()
        if stripped.startswith(">>>"):
            while i < len(lines) and lines[i].strip():  # a doctest runs to the next blank line
                i += 1
            continue
        m = _DIRECTIVE.match(line)
        literal = stripped.endswith("::") and not m
        if m or literal:
            base = _indent(line)
            if literal:
                out.append(line[: len(line) - 1])  # "text::" shows "text:"
            i += 1
            while i < len(lines) and (not lines[i].strip() or _indent(lines[i]) > base):
                i += 1
            continue
        out.append(line)
        i += 1
    return out


def _drop_name_lines(text: str) -> str:
    """``text`` without the name-and-type lines of the numpydoc sections that list names, and
    without section headings."""
    out: list[str] = []
    section = ""
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        line = lines[i]
        if i + 1 < len(lines) and re.fullmatch(r"-{3,}", lines[i + 1].strip()) and line.strip():
            section = line.strip()
            i += 2
            continue
        if section in _NAME_SECTIONS and line.strip() and _indent(line) == 0:
            i += 1
            continue
        out.append(line)
        i += 1
    return "\n".join(out)


def prose(doc: str) -> str:
    """The text a reader sees as prose in a numpydoc docstring ``doc``."""
    text = "\n".join(_drop_blocks(inspect.cleandoc(doc).split("\n")))
    text = _drop_name_lines(text)
    text = _ROLE.sub(" ", text)
    text = _LITERAL.sub(" ", text)
    text = _BACKTICK_NAME.sub(" ", text)
    text = _STRONG.sub(r"\1", text)
    text = _WORDS.sub(" ", text)
    return _URL.sub(" ", text)


def plain_math(doc: str) -> list[tuple[str, str]]:
    """The (kind, text) of each plain-text math pattern in the prose of ``doc``."""
    text = prose(doc)
    return [
        (kind, " ".join(m.group(0).split())) for kind, pat in PATTERNS.items() for m in pat.finditer(text)
    ]


@pytest.mark.parametrize(
    ("doc", "kinds"),
    [
        ("Agrees to 1e-6 relative.", ["e-notation"]),
        ("Agrees to :math:`10^{-6}` relative.", []),
        ("The update P = F P F^T + Q.", ["power"]),
        ("The update\n\n.. math::\n\n   P = F P F^T + Q\n\nof Eq. (3).", []),
        ("The update :math:`P = F P F^T + Q` of Eq. (3).", []),
        ("The clock's sigma_0 in ns.", ["flat subscript", "Greek name"]),
        ("The clock's :math:`\\sigma_0` in ns.", []),
        ("Scale 1/sqrt(3b).", ["sqrt("]),
        ("Scale :math:`1/\\sqrt{3b}`.", []),
        (
            "A clock.\n\nParameters\n----------\nsigma_0 : float, default 1e-6\n"
            "    The standard deviation :math:`\\sigma_0`, in s.\n\nReturns\n-------\n"
            "P_DL : float\n    The probability.",
            [],
        ),
        (
            "A clock.\n\nParameters\n----------\nsigma_0 : float\n    Its sigma_0 in s.",
            ["flat subscript", "Greek name"],
        ),
        ("Example.\n\nExamples\n--------\n>>> sigma_0 = 1e-6\n>>> sigma_0 ** 2\n1e-12", []),
        ("Use ``sigma_0 ** 2`` or :func:`rms_xy` or `sigma_0`, see https://x.org/a_b.", []),
        ("Decides when **more than** half agree, not x**2.", ["power"]),
        ("A chi-square law, an incomplete gamma function; chi = 2.", ["Greek name"]),
        ("Code::\n\n    x = a_b ** 2\n\nends.", []),
        ("The 1-:math:`\\sigma` noise, 3 dB, 0.5 s, Eq. (3.8.16), Table 2.1.", []),
    ],
)
def test_detector_finds_plain_math_in_prose_only(doc, kinds):
    assert sorted({k for k, _ in plain_math(doc)}) == sorted(kinds)


def _attr_docs(module: object) -> list[tuple[str, str]]:
    """The ``#:`` documentation of the public data of ``module`` (what autodoc renders)."""
    from sphinx.pycode import ModuleAnalyzer

    names = set(getattr(module, "__all__", ()))
    docs = ModuleAnalyzer.for_module(module.__name__).find_attr_docs()
    return [
        (f"{module.__name__}.{name}", "\n".join(lines))
        for (cls, name), lines in docs.items()
        if not cls and name in names
    ]


def api_docstrings() -> list[tuple[str, str]]:
    """(object, docstring) of what the API reference renders."""
    docs: list[tuple[str, str]] = []
    modules = _modules()
    packages = {m.__name__.rpartition(".")[0] for m in modules if m.__name__.count(".") == 2}
    for name in sorted(packages | {m.__name__ for m in modules}):
        mod = importlib.import_module(name)
        docs.append((name, mod.__doc__ or ""))
    for mod in modules:
        docs += _attr_docs(mod)
    for name, obj in PUBLIC:
        docs.append((name, obj.__doc__ or ""))
        if inspect.isclass(obj):
            for attr, member in vars(obj).items():
                if attr.startswith("_"):
                    continue
                if isinstance(member, (staticmethod, classmethod)):
                    member = member.__func__
                if isinstance(member, property):
                    member = member.fget
                if inspect.isroutine(member) or inspect.isclass(member):
                    docs.append((f"{name}.{attr}", getattr(member, "__doc__", None) or ""))
    return docs


_LITERAL_SPAN = re.compile(r"``(.+?)``", re.S)


def _is_python(text: str) -> bool:
    text = " ".join(text.split())
    for mode in ("eval", "exec"):
        try:
            ast.parse(text, mode=mode)
        except SyntaxError:
            continue
        return True
    return False


def literal_formulas(doc: str) -> list[str]:
    """The ``literal`` spans of ``doc``'s prose that hold a plain-math pattern and are not Python."""
    text = _drop_name_lines("\n".join(_drop_blocks(inspect.cleandoc(doc).split("\n"))))
    found = []
    for m in _LITERAL_SPAN.finditer(text):
        span = m.group(1)
        if any(p.search(span) for p in PATTERNS.values()) and not _is_python(span):
            found.append(" ".join(span.split()))
    return found


@pytest.mark.parametrize(
    ("doc", "found"),
    [
        ("The trace ``tr{(F'F)^-1}`` of Eq. 4.1.", ["tr{(F'F)^-1}"]),
        ("The gain ``sigma^2 gamma_n``.", ["sigma^2 gamma_n"]),
        ("Computed as ``x ** (1/3)`` with ``tau_bar = 0``.", []),
        ("The gain :math:`\\sigma^2 \\gamma_n`, see ``navcore.units.G0``.", []),
        ("Doctest.\n\n>>> ``a^2 b``", []),
    ],
)
def test_literal_formula_detector(doc, found):
    assert literal_formulas(doc) == found


def test_formulas_in_literals_only_shrink():
    hits = {(who, text) for who, doc in api_docstrings() for text in literal_formulas(doc)}
    todo = set()
    for line in LITERAL_TODO.read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            who, text = line.split("\t")
            todo.add((who, text))
    new = sorted(hits - todo)
    done = sorted(todo - hits)
    assert not new, "formulas in ``literal`` spans (set them as :math:):\n" + "\n".join(
        "\t".join(h) for h in new
    )
    assert not done, f"fixed now, remove from {LITERAL_TODO.name}:\n" + "\n".join("\t".join(h) for h in done)


def _hits() -> set[tuple[str, str, str]]:
    return {(who, kind, text) for who, doc in api_docstrings() for kind, text in plain_math(doc)}


def _todo() -> set[tuple[str, str, str]]:
    entries = set()
    for line in TODO.read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            who, kind, text = line.split("\t")
            entries.add((who, kind, text))
    return entries


def test_api_docstrings_set_every_formula_as_math():
    docs = api_docstrings()
    assert len(docs) > 500  # modules, functions, classes and methods of the nine subpackages
    hits = _hits()
    todo = _todo()
    new = sorted(hits - todo)
    done = sorted(todo - hits)
    assert not new, "plain-text math in API docstrings (set it as :math:):\n" + "\n".join(
        "\t".join(h) for h in new
    )
    assert not done, f"fixed now, remove from {TODO.name}:\n" + "\n".join("\t".join(h) for h in done)


_CITATION = re.compile(r"^\.\. \[[^\]]+\][ \t]+\S.*(?:\n(?:[ \t]+\S.*|[ \t]*)$)*", re.M)


def test_api_references_are_not_read_as_lists():
    """A reference whose text begins with an initial ("P. S. Maybeck, ...") on one line is read
    by docutils as a list enumerated "P.", "S." (issue 32, item 4: "P.   S. Maybeck" in the
    PDF's API reference). The book's API-reference extension escapes that initial: every
    citation of every API docstring, so escaped, parses without a list.

    Oracle: docutils itself, which parses each citation as Sphinx does; it reads the
    hand-written first case, unescaped, as a list."""
    import importlib.util

    from docutils.core import publish_doctree

    spec = importlib.util.spec_from_file_location(
        "api_reference", ROOT / "book" / "_ext" / "api_reference.py"
    )
    assert spec is not None and spec.loader is not None
    ext = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(ext)

    def is_list(citation: str, escape: bool = True) -> bool:
        lines = citation.splitlines()
        if escape:
            ext.escape_citation_initials(lines)
        tree = publish_doctree(
            "\n".join(lines) + "\n", settings_overrides={"report_level": 5, "halt_level": 5}
        )
        return "<enumerated_list" in tree.pformat()

    maybeck = ".. [2] P. S. Maybeck, Stochastic Models, Vol. 1 (1979), Ch. 6."
    assert is_list(maybeck, escape=False) and not is_list(maybeck)
    assert "P. S. Maybeck" in publish_doctree("\n".join(_escaped([maybeck], ext))).astext()
    citations = [
        (who, m.group(0)) for who, doc in api_docstrings() for m in _CITATION.finditer(inspect.cleandoc(doc))
    ]
    assert any(is_list(c, escape=False) for _, c in citations)  # the API has such references
    bad = [f"{who}: {c.splitlines()[0]}" for who, c in citations if is_list(c)]
    assert not bad, "references read as enumerated lists:\n" + "\n".join(bad)


def _escaped(lines: list[str], ext) -> list[str]:
    lines = list(lines)
    ext.escape_citation_initials(lines)
    return lines


def test_api_docstrings_hold_no_control_character():
    """A backslash in a docstring that is not raw can make a control character: ``\\a`` in
    ``"``\\allowbreak{}``"`` is BEL, which the PDF build cannot typeset (it failed a CI run
    once). Oracle: the characters themselves, below a space and not a tab or newline."""
    bad = [
        (name, hex(ord(ch)))
        for name, doc in api_docstrings()
        for ch in doc
        if ord(ch) < 32 and ch not in "\n\t"
    ]
    assert not bad, f"control characters in docstrings (a raw docstring or a doubled backslash): {bad}"
