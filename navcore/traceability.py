"""The traceability index: paper item -> navcore function -> tests -> book pages, and back.

Sources, all read from the checkout (nothing is typed in):

* the ``@implements`` records of the model functions (:func:`implementations`);
* the book's pages (``book/**/*.md``): an equation is *displayed* on a page when a display
  equation carries the label ``eq-<paper>-<number>`` (the label convention of
  ``book/_ext/paper_equations.py``), and an item is *mentioned* when the page's text names it
  ("Eq. (13)", "Eqs. (2.4.1)-(2.4.2)", "Table 2.6", "Fig. 2.1", "Sec. 2.5", "Appendix C");
* the tests (``tests/*.py``), scanned with :mod:`ast` for the functions they use;
* the ledger's claims (their ``locator``), and the papers' texts (``../shared/papers``), which
  say which equations, tables, figures and sections exist.

:func:`build_index` assembles it; :func:`problems` lists what breaks the chain (a function
claiming an item that no page shows, a label or a claim naming an item the paper lacks);
``tests/test_traceability.py`` fails on any problem, and ``book/traceability.md`` shows the
index.
"""

from __future__ import annotations

import ast
import importlib
import json
import re
from collections import defaultdict
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

from navcore import coverage
from navcore.coverage import ITEMS_SNAPSHOT
from navcore.trace import Implementation, Ref, recorded

__all__ = [
    "BookPage",
    "Index",
    "all_implementations",
    "build_index",
    "index_markdown",
    "items_in_text",
    "paper_equation_number",
    "paper_items",
    "paper_items_from_text",
    "problems",
    "reverse_markdown",
    "write_items_snapshot",
]

ROOT = Path(__file__).resolve().parents[1]
CHAPTER_PAPER = {"wf": "WF", "sp": "SP", "atc10": "ATC10", "kzl": "KZL"}
PAPER_FILES = {
    "WF": "wu-fowler-mems-emitter-location.txt",
    "SP": "schmidt-phillips-insgps-architecture-comparisons.txt",
    "ATC10": "lincoln-atc10-satellite-surveillance-1972.txt",
    "KZL": "knedlik-zhou-loffeld-bistatic-sar-attitude.txt",
}
_NUM = r"(?:[A-H]\.)?\d+(?:\.\d+)*[a-z]?"
_LABEL = re.compile(r"\$\$\s*\((eq-(?:wf|sp|atc10|kzl)-[^)\s]+)\)")
#: A decorated function's first line: the module records paper items (``navcore.trace``).
_DECORATES = re.compile(r"^[ \t]*@implements\(", re.M)
#: An erratum box, rendered on the page from its ``Erratum`` object (``{erratum} ID``).
_ERRATUM_BOX = re.compile(r"^```\{erratum\}[ \t]+(\S+)", re.M)
_PAPER_LABEL = re.compile(r"^eq-(?:wf|sp|atc10|kzl)-(?P<number>(?:[a-z]\.?)?\d+[a-z]?(?:\.\d+[a-z]?)*)$")
_EQ_MENTION = re.compile(
    r"\bEq(?:uation)?s?\.?\s*\(?(" + _NUM + r")\)?((?:\s*(?:,|-|–|to|and|&)\s*\(?" + _NUM + r"\)?)*)"
)
_MORE_NUM = re.compile(r"\(?(" + _NUM + r")\)?")
_LABELLED = {
    "Table": re.compile(r"\bTables?\s+((?:[A-Z]\.)?\d+(?:\.\d+)*)((?:\s*(?:,|-|–|and)\s*\d+(?:\.\d+)*)*)"),
    "Fig.": re.compile(r"\bFig(?:ure)?s?\.?\s+(\d+(?:\.\d+)*)((?:\s*(?:,|-|–|and)\s*\d+(?:\.\d+)*)*)"),
    "Sec.": re.compile(r"\bSec(?:tion)?s?\.?\s+(\d+(?:\.\d+)*|[IV]+(?:\.[A-D])?)"),
    "Appendix": re.compile(r"\b(?:Appendi(?:x|ces)|App\.)\s+([A-H])\b"),
    "Theorem": re.compile(r"\bTheorem\s+(\d+(?:\.\d+)*)"),
    "Remark": re.compile(r"\bRemark\s+\(?([ivx]+)\)"),
    # a numbered rule as the paper prints it, "(1)" in a list of rules (ATC-10 Sec. 4.6's rules of thumb)
    "Rule": re.compile(r"\b[Rr]ules?\s+\((\d+)\)((?:\s*(?:,|-|–|and)\s*\(\d+\))*)"),
    # a worked example numbered in roman numerals (ATC-10 Sec. 4.6's Examples I and II)
    "Example": re.compile(r"\bExamples?\s+(I{1,3})\b((?:\s*(?:,|and)\s*I{1,3}\b)*)"),
}


def paper_equation_number(label: str) -> str | None:
    """The paper's equation number encoded in a book label (``eq-atc10-a.18`` -> ``A.18``).

    Parameters
    ----------
    label : str
        A display equation's label, ``eq-<paper>-<number>`` (the paper key in lower case).

    Returns
    -------
    str or None
        The number as the paper prints it (an appendix letter in upper case, followed by a
        dot); ``None`` for a label of another form (``eq-wf-x-<name>``, the book's own
        equations).

    Examples
    --------
    >>> paper_equation_number("eq-atc10-a.18"), paper_equation_number("eq-wf-x-gain")
    ('A.18', None)
    """
    match = _PAPER_LABEL.match(label)
    if match is None:
        return None
    number = match["number"]
    if number[0].isalpha():
        number = number[0].upper() + ("" if number[1] == "." else ".") + number[1:]
    return number


def _expand(first: str, rest: str) -> list[str]:
    """``13`` and ``-(14)`` -> 13, 14; integer ranges are filled in, dotted ones keep ends."""
    numbers = [first, *_MORE_NUM.findall(rest)]
    out = list(numbers)
    if (len(numbers) == 2 and "-" in rest) or "–" in rest or " to " in rest:
        a, b = numbers[0], numbers[-1]
        head_a, _, tail_a = a.rpartition(".")
        head_b, _, tail_b = b.rpartition(".")
        if head_a == head_b and tail_a.isdigit() and tail_b.isdigit() and 0 < int(tail_b) - int(tail_a) < 30:
            prefix = f"{head_a}." if head_a else ""
            out = [f"{prefix}{i}" for i in range(int(tail_a), int(tail_b) + 1)]
    return out


_DOTTED = re.compile(r"\((?:\\text\{)?((?:[A-H]\.)?\d+(?:\.\d+)+[a-z]?|[A-H]\.\d+[a-z]?)\}?\)")

_DOTTED_RANGE = re.compile(
    r"\(((?:[A-H]\.)?\d+(?:\.\d+)+|[A-H]\.\d+)\)\s*(?:-|–|to)\s*\(((?:[A-H]\.)?\d+(?:\.\d+)+|[A-H]\.\d+)\)"
)

#: Items the papers' OCR texts lost (their numbers or headings), checked by hand against the
#: texts: each is named by the book or the ledger, and the reason says where it stands.
OCR_LOST = {
    "ATC10 4.5.38": "the gamma_n extrapolation formula after (4.5.37) is printed without its tag",
    "ATC10 4.6.2": "Sec. 4.6's equations lost their tags in the OCR text",
    "ATC10 G.5": "Appendix G keeps only the tag (G.1); the V0(rho) integral follows it untagged",
    "ATC10 Fig. 2.10": "the captions of Figs. 2.10, 2.13, 2.14 and 2.16 are missing from the OCR text",
    "ATC10 Fig. 2.13": "the captions of Figs. 2.10, 2.13, 2.14 and 2.16 are missing from the OCR text",
    "ATC10 Fig. 2.14": "the captions of Figs. 2.10, 2.13, 2.14 and 2.16 are missing from the OCR text",
    "ATC10 Fig. 2.16": "the captions of Figs. 2.10, 2.13, 2.14 and 2.16 are missing from the OCR text",
    "KZL 10": "the KZL text keeps the tags (3), (4), (7)-(9) and (16) only; (10) is the 17-state model",
    "SP Sec. 2.4": "the heading of Sec. 2.4 (IMU quality, Table 2.5) is lost; 2.3 and 2.5 surround it",
}


def items_in_text(text: str, *, dotted: bool = False) -> set[str]:
    """The paper items a piece of prose names (equations as numbers; others with their kind).

    ``dotted`` also counts a bare parenthesised dotted number such as "(2.4.2)" or "(A.18)"
    as an equation (safe for the chapters of the papers with sectioned equation numbers).

    Parameters
    ----------
    text : str
        Prose, a page's Markdown or a claim's locator.
    dotted : bool, optional
        Also count bare parenthesised dotted numbers as equations.

    Returns
    -------
    set of str
        Equation numbers (``"13"``, ``"2.4.2"``; an integer range such as "Eqs. (13)-(15)"
        is filled in) and labelled items (``"Table 2.6"``, ``"Fig. 2.1"``, ``"Sec. 2.5"``,
        ``"Appendix C"``, ``"Theorem 1"``, ``"Remark ii"``, ``"Rule 1"`` for a printed rule "(1)",
        ``"Example II"``).

    Examples
    --------
    >>> sorted(items_in_text("Eqs. (13)-(15) and Table 2.6 of Sec. 2.5"))
    ['13', '14', '15', 'Sec. 2.5', 'Table 2.6']
    """
    found: set[str] = set()
    for m in _EQ_MENTION.finditer(text):
        found.update(_expand(m.group(1), m.group(2) or ""))
    if dotted:
        found.update(_DOTTED.findall(text))
        for m in _DOTTED_RANGE.finditer(text):
            found.update(_expand(m.group(1), "-" + m.group(2)))
    for kind, rx in _LABELLED.items():
        for m in rx.finditer(text):
            rest = m.group(2) if rx.groups > 1 else ""
            numbers = [m.group(1), *re.findall(r"I{1,3}", rest or "")] if kind == "Example" else None
            for number in numbers or _expand(m.group(1), rest or ""):
                found.add(f"{kind} {number}")
    return found


def paper_text_path(paper: str) -> Path:
    """Where the paper's text is expected: ``../shared/papers`` beside the checkout."""
    return ROOT.parent / "shared" / "papers" / PAPER_FILES[paper]


@cache
def paper_items(paper: str) -> frozenset[str] | None:
    """Equations, tables, figures and sections of the paper: from its text, else the snapshot.

    ``None`` only when neither the text nor the committed snapshot has the paper.

    Parameters
    ----------
    paper : str
        Paper key (``"WF"``).

    Returns
    -------
    frozenset of str or None
        The items, spelled as :func:`items_in_text` spells them.

    Examples
    --------
    >>> items = paper_items("WF")
    >>> "13" in items
    True
    """
    found = paper_items_from_text(paper)
    if found is not None:
        return found
    if ITEMS_SNAPSHOT.exists():
        snap = json.loads(ITEMS_SNAPSHOT.read_text())
        if paper in snap:
            return frozenset(snap[paper])
    return None


def write_items_snapshot() -> Path:
    """Write :data:`~navcore.coverage.ITEMS_SNAPSHOT` from the papers' texts (all four must be present).

    The printed-item inventory kept in the same file (key ``"printed"``, read by
    :mod:`navcore.coverage`) is carried over unchanged. The file is part of the source tree,
    so this is a maintenance step, run by hand after a paper's text changes.

    Returns
    -------
    pathlib.Path
        The snapshot's path.

    Raises
    ------
    ValueError
        If a paper's text is absent.
    """
    items = {p: paper_items_from_text(p) for p in PAPER_FILES}
    missing = [p for p, v in items.items() if v is None]
    if missing:
        where = paper_text_path(missing[0])
        raise ValueError(f"the papers' texts are absent for {missing}: expected at {where}")
    data: dict[str, object] = {p: sorted(v or ()) for p, v in items.items()}
    if ITEMS_SNAPSHOT.exists():  # the printed-item inventory (navcore.coverage) is kept as it is
        old = json.loads(ITEMS_SNAPSHOT.read_text())
        if "printed" in old:
            data["printed"] = old["printed"]
    ITEMS_SNAPSHOT.write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n")
    return ITEMS_SNAPSHOT


@cache
def paper_items_from_text(paper: str) -> frozenset[str] | None:
    """Equations, tables, figures and sections that the paper's text contains (None if absent).

    Parameters
    ----------
    paper : str
        Paper key (``"WF"``); its text is looked for at :func:`paper_text_path`.

    Returns
    -------
    frozenset of str or None
        The items named in the text (:func:`items_in_text` with ``dotted``), the equation
        tags, the section and appendix headings, the remarks and the numbered rules; ``None``
        when the text is absent.

    Examples
    --------
    >>> found = paper_items_from_text("WF")
    >>> found is None or "13" in found
    True
    """
    path = paper_text_path(paper)
    if not path.exists():
        return None
    text = path.read_text()
    items = set(items_in_text(text, dotted=True))
    section = None  # lettered subsections under a roman-numbered section (WF: "IV." then "C.")
    for line in text.splitlines():
        roman = re.match(r"^(?:#+\s*)?([IVX]+)\.\s+[A-Z]", line)
        letter = re.match(r"^(?:#+\s*)?([A-H])\.\s+[A-Z][a-z]", line)
        if roman:
            section = roman.group(1)
        elif letter and section:
            items.add(f"Sec. {section}.{letter.group(1)}")
    items.update(re.findall(r"\\tag\{(" + _NUM + r")\}", text))
    items.update(re.findall(r"\((" + _NUM + r")\)", text))
    items.update(f"Sec. {m}" for m in re.findall(r"(?m)^(?:#+\s*)?(\d+(?:\.\d+)*)\.?\s+[A-Z]", text))
    items.update(f"Sec. {m}" for m in re.findall(r"(?m)^(?:#+\s*)?([IV]+(?:\.[A-D])?)\.?\s+[A-Z]", text))
    for block in re.findall(r"Remarks?:(.{0,3000})", text, flags=re.S):  # "Remarks: (i) ... (ii) ..."
        items.update(f"Remark {m}" for m in re.findall(r"\(([ivx]+)\)", block))
    for block in re.findall(r"rules of thumb:(.{0,3000})", text, flags=re.S):  # "rules of thumb: - (1) ..."
        items.update(f"Rule {m}" for m in re.findall(r"(?m)^-?\s*\((\d+)\)\s", block))
    appendix = re.compile(r"(?m)^(?:#+\s*)?APPENDIX\s+([A-H])\b", flags=re.I)
    items.update(f"Appendix {m}" for m in appendix.findall(text))
    return frozenset(items)


@dataclass(frozen=True)
class BookPage:
    """One page of the book: its docname, title, chapter paper, labels and mentions.

    Attributes
    ----------
    docname : str
        The page's path under ``book/`` without suffix (``"atc10/21-roc-bounds"``).
    title : str
        Its first level-one heading.
    paper : str or None
        The paper key of its chapter; ``None`` for a page outside the chapters.
    displayed : frozenset of str
        The paper's equation numbers the page displays with a label.
    labels : tuple of str
        Every ``eq-<paper>-...`` label on the page.
    mentioned : frozenset of str
        The paper items its text names (:func:`items_in_text` with ``dotted``).

    Examples
    --------
    >>> page = BookPage("wf/01-location-error", "Location error", "WF", frozenset({"13"}),
    ...                 ("eq-wf-13",), frozenset({"13", "Table 1"}))
    >>> page.paper, sorted(page.mentioned)
    ('WF', ['13', 'Table 1'])
    """

    docname: str
    title: str
    paper: str | None
    displayed: frozenset[str]  # paper equation numbers with a labelled display
    labels: tuple[str, ...]
    mentioned: frozenset[str]


def _with_erratum_boxes(text: str) -> str:
    """A page's source with the words of the erratum boxes it renders appended.

    A box's text lives in its ``Erratum`` object, not in the page, but the reader sees it on
    the page: the items it names are mentioned there.
    """
    ids = _ERRATUM_BOX.findall(text)
    if not ids:
        return text
    from navcore import ledger

    boxes = [ledger.erratum(i) for i in ids]
    return "\n".join([text, *(f"{e.locator}. {e.printed} {e.finding} {e.evidence}" for e in boxes)])


@cache
def book_pages() -> tuple[BookPage, ...]:
    pages = []
    book = ROOT / "book"
    for path in sorted(book.rglob("*.md")):
        if "_build" in path.parts or path.name.startswith("_"):
            continue
        rel = path.relative_to(book).with_suffix("").as_posix()
        text = _with_erratum_boxes(path.read_text())
        title = next((ln[2:].strip() for ln in text.splitlines() if ln.startswith("# ")), rel)
        labels = tuple(_LABEL.findall(text))
        numbers = {paper_equation_number(label) for label in labels}
        pages.append(
            BookPage(
                docname=rel,
                title=title,
                paper=CHAPTER_PAPER.get(rel.split("/")[0]) if "/" in rel else None,
                displayed=frozenset(n for n in numbers if n),
                labels=labels,
                mentioned=frozenset(items_in_text(text, dotted=True)),
            )
        )
    return tuple(pages)


@cache
def functions_used_by_tests() -> dict[str, tuple[str, ...]]:
    """Function name -> the test files that use it (imports, calls, attribute access)."""
    uses: dict[str, set[str]] = defaultdict(set)
    for path in sorted((ROOT / "tests").glob("test_*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Name):
                uses[node.id].add(path.name)
            elif isinstance(node, ast.Attribute):
                uses[node.attr].add(path.name)
            elif isinstance(node, ast.ImportFrom):
                for alias in node.names:
                    uses[alias.name].add(path.name)
    return {k: tuple(sorted(v)) for k, v in uses.items()}


@dataclass
class Entry:
    """One paper item with everything that refers to it.

    ``claims`` are the claims whose locator names the item; for an equation that no locator
    names, the claims that the coverage inventory (:mod:`navcore.coverage`) says check it, such
    as a claim filed under a neighbouring equation.
    """

    ref: Ref
    functions: list[Implementation] = field(default_factory=list)
    displayed_on: list[BookPage] = field(default_factory=list)
    mentioned_on: list[BookPage] = field(default_factory=list)
    tests: set[str] = field(default_factory=set)
    claims: list[str] = field(default_factory=list)


@dataclass
class Index:
    """The traceability index, as :func:`build_index` assembles it.

    Attributes
    ----------
    entries : dict of Ref to Entry
        Each paper item named anywhere, with the functions implementing it, the pages that
        display or mention it, the tests using those functions and the claims that locate it
        (or, for an equation no locator names, that the coverage inventory says check it).
    implementations : tuple of Implementation
        Every decorated navcore function (:func:`all_implementations`).

    Examples
    --------
    >>> from navcore.trace import Implementation, Ref
    >>> from navcore.traceability import Entry
    >>> ref = Ref("ATC10", "3.5.5")
    >>> impl = Implementation("navcore.detection.roc_bounds", "chernoff_log_tail", (ref,))
    >>> idx = Index({ref: Entry(ref, functions=[impl])}, (impl,))
    >>> [str(e.ref) for e in idx.by_paper("ATC10")]
    ['ATC10 3.5.5']
    """

    entries: dict[Ref, Entry]
    implementations: tuple[Implementation, ...]

    def by_paper(self, paper: str) -> list[Entry]:
        def key(e: Entry) -> tuple:
            item = e.ref.item
            kind = 0 if e.ref.is_equation else 1
            parts = re.findall(r"\d+|[A-Za-z]+", item)
            return (kind, [(0, int(p)) if p.isdigit() else (1, p) for p in parts])

        return sorted((e for e in self.entries.values() if e.ref.paper == paper), key=key)


def claim_refs(locator: str, paper: str) -> list[Ref]:
    """The items a claim's locator names, as references of its paper."""
    return [Ref(paper, item) for item in sorted(items_in_text(locator, dotted=True))]


def _inventory_claims() -> dict[Ref, list[str]]:
    """Equation -> the claims the coverage inventory names for it (in the inventory's order)."""
    out: dict[Ref, list[str]] = {}
    for it in coverage.items():
        if it.category != "equation" or not it.claims:
            continue
        for ref in claim_refs(it.locator, it.paper):
            if ref.is_equation:
                known = out.setdefault(ref, [])
                known.extend(c for c in it.claims if c not in known)
    return out


def all_implementations() -> tuple[Implementation, ...]:
    """Every ``@implements`` record of navcore, after importing the modules that decorate.

    The modules are found by their source (a line that starts with ``@implements(``), so that
    only they are imported: the models and paper modules, below this module, never the book
    or report modules above it.

    Returns
    -------
    tuple of Implementation
        One per decorated function, sorted by full name (:func:`navcore.trace.recorded`).
        Importing the paper modules takes seconds.

    Examples
    --------
    >>> impl = next(i for i in all_implementations() if i.qualname == "chernoff_log_tail")
    >>> impl.module, [str(r) for r in impl.refs]
    ('navcore.detection.roc_bounds', ['ATC10 3.5.5', 'ATC10 3.5.6', 'ATC10 3.5.7'])
    """
    package = Path(__file__).resolve().parent
    for path in sorted(package.rglob("*.py")):
        if _DECORATES.search(path.read_text(encoding="utf-8")):
            parts = path.relative_to(package.parent).with_suffix("").parts
            importlib.import_module(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return recorded()


@cache
def build_index() -> Index:
    """Assemble the index from the decorators, the book's pages, the tests and the ledger.

    Imports every navcore module (:func:`all_implementations`) and every paper's claims,
    so the first call takes seconds; the result is cached.

    Returns
    -------
    Index
        Every paper item that a function implements, a claim locates or a page displays,
        with the pages that mention it. An equation that no claim's locator names takes the
        claims the coverage inventory gives it (a claim filed under a neighbouring equation).
    """
    from navcore import ledger

    implementations = all_implementations()
    entries: dict[Ref, Entry] = {}

    def entry(ref: Ref) -> Entry:
        return entries.setdefault(ref, Entry(ref))

    uses = functions_used_by_tests()
    for impl in implementations:
        for ref in impl.refs:
            e = entry(ref)
            e.functions.append(impl)
            e.tests.update(uses.get(impl.qualname.split(".")[-1], ()))
    for claim in ledger.claims():
        for ref in claim_refs(claim.locator, claim.paper):
            entry(ref).claims.append(claim.id)
    for ref, claims in _inventory_claims().items():  # checked under a neighbouring equation
        if ref in entries and not entries[ref].claims:
            entries[ref].claims.extend(claims)
    for page in book_pages():
        if page.paper is None:
            continue
        for number in page.displayed:
            entry(Ref(page.paper, number)).displayed_on.append(page)
    for ref, e in entries.items():
        e.mentioned_on = [
            p
            for p in book_pages()
            if p.paper == ref.paper and ref.item in p.mentioned and p not in e.displayed_on
        ]
    return Index(entries, implementations)


def problems(index: Index | None = None) -> list[str]:
    """Every broken link of the chain, as sentences (empty when the index is whole).

    Parameters
    ----------
    index : Index or None, optional
        The index to check; ``None`` builds the whole one (:func:`build_index`, which
        imports every navcore module and the ledger's claims).

    Returns
    -------
    list of str
        A function's item shown on no page of its paper's chapter, an item that is not in
        the paper's text (nor known lost from it), a label of neither book form. The book's
        pages are always checked.

    Examples
    --------
    >>> from navcore.trace import Implementation, Ref
    >>> from navcore.traceability import Entry
    >>> ref = Ref("ATC10", "3.5.5")
    >>> impl = Implementation("navcore.detection.roc_bounds", "chernoff_log_tail", (ref,))
    >>> idx = Index({ref: Entry(ref, functions=[impl])}, (impl,))
    >>> for problem in problems(idx):  # doctest: +NORMALIZE_WHITESPACE
    ...     print(problem)
    ATC10 3.5.5: implemented by navcore.detection.roc_bounds.chernoff_log_tail but shown on
    no page of the ATC10 chapter
    """
    index = index or build_index()
    out = []
    for ref, e in sorted(index.entries.items()):
        if e.functions and not (e.displayed_on or e.mentioned_on):
            names = ", ".join(f.name for f in e.functions)
            out.append(f"{ref}: implemented by {names} but shown on no page of the {ref.paper} chapter")
        known = paper_items(ref.paper)
        if known is not None and ref.item not in known and str(ref) not in OCR_LOST:
            who = [f.name for f in e.functions] + e.claims + [p.docname for p in e.displayed_on]
            out.append(f"{ref}: not an item of the paper's text (named by {', '.join(who)})")
    for page in book_pages():
        if page.paper is None:
            continue
        for label in page.labels:
            if label.startswith(f"eq-{page.paper.lower()}-x-"):
                continue
            if paper_equation_number(label) is None:
                out.append(
                    f"{page.docname}: label {label!r} is neither eq-<paper>-<number> nor eq-<paper>-x-<name>"
                )
    return out


def _page_link(page: BookPage, displayed: bool) -> str:
    mark = "\u00a0★" if displayed else ""
    return f"{{doc}}`{page.docname.split('/')[-1]} </{page.docname}>`{mark}"


def _boxed(rows: list[str]) -> str:
    """A Markdown table in a container the book's CSS sets in a smaller font."""
    return "```{container} trace-table\n" + "\n".join(rows) + "\n```"


def _function_link(module: str, qualname: str, text: str) -> str:
    """``text`` as a link to the API reference when the function is public there, else code."""
    import importlib

    if module.startswith("navcore.papers") or "." in qualname:
        return f"`{text}`"
    try:
        public = qualname in getattr(importlib.import_module(module), "__all__", ())
    except ImportError:
        public = False
    return f"{{py:func}}`{text} <{module}.{qualname}>`" if public else f"`{text}`"


def index_markdown(paper: str, index: Index | None = None) -> str:
    """The paper's items as a Markdown table: functions, tests, pages, claims.

    Parameters
    ----------
    paper : str
        Paper key (``"ATC10"``).
    index : Index or None, optional
        The index to show; ``None`` builds the whole one (:func:`build_index`).

    Returns
    -------
    str
        A MyST ``container`` block (class ``trace-table``) holding the table: one row per
        item of the paper, with the functions (linked to the API reference when public),
        the test files, the pages (a star where displayed) and the number of claims.

    Examples
    --------
    >>> from navcore.trace import Implementation, Ref
    >>> from navcore.traceability import Entry
    >>> ref = Ref("ATC10", "3.5.5")
    >>> impl = Implementation("navcore.detection.roc_bounds", "chernoff_log_tail", (ref,))
    >>> idx = Index({ref: Entry(ref, functions=[impl])}, (impl,))
    >>> md = index_markdown("ATC10", idx)
    >>> print(md.splitlines()[1])
    | Item | navcore | Tests | Book | Claims |
    >>> "<navcore.detection.roc_bounds.chernoff_log_tail>" in md
    True
    """
    index = index or build_index()
    rows = ["| Item | navcore | Tests | Book | Claims |", "|---|---|---|---|---|"]
    for e in index.by_paper(paper):
        item = f"Eq.\u00a0({e.ref.item})" if e.ref.is_equation else e.ref.item
        funcs = "<br>".join(_function_link(f.module, f.qualname, f.qualname) for f in e.functions) or "—"
        tests = "<br>".join(t.removesuffix(".py") for t in sorted(e.tests)) or "—"
        pages = [_page_link(p, True) for p in e.displayed_on] + [_page_link(p, False) for p in e.mentioned_on]
        rows.append(f"| {item} | {funcs} | {tests} | {'<br>'.join(pages) or '—'} | {len(e.claims) or '—'} |")
    return _boxed(rows)


def reverse_markdown(index: Index | None = None) -> str:
    """Each decorated navcore function and the paper items it implements.

    Parameters
    ----------
    index : Index or None, optional
        The index to show; ``None`` builds the whole one (:func:`build_index`).

    Returns
    -------
    str
        A MyST ``container`` block (class ``trace-table``) holding a two-column Markdown
        table: the function (linked to the API reference when public) and its items.

    Examples
    --------
    >>> from navcore.trace import Implementation, Ref
    >>> from navcore.traceability import Entry
    >>> ref = Ref("ATC10", "3.5.5")
    >>> impl = Implementation("navcore.detection.roc_bounds", "chernoff_log_tail", (ref,))
    >>> idx = Index({ref: Entry(ref, functions=[impl])}, (impl,))
    >>> print(reverse_markdown(idx).splitlines()[-2].split(" | ")[-1])
    ATC10 Eq. (3.5.5) |
    """
    index = index or build_index()
    rows = ["| navcore function | Implements |", "|---|---|"]
    for impl in index.implementations:
        refs = ", ".join(f"{r.paper} Eq. ({r.item})" if r.is_equation else str(r) for r in impl.refs)
        text = f"{impl.module.removeprefix('navcore.')}.{impl.qualname}"
        rows.append(f"| {_function_link(impl.module, impl.qualname, text)} | {refs} |")
    return _boxed(rows)
