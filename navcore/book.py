"""Helpers for the book's notebooks: style, ledger rows, figures, summary boxes.

A chapter typically starts with::

    from navcore import book
    book.setup()
    book.chapter_summary("WF")          # counts of the chapter's claims by status

shows a registered figure (glued, so the Markdown can give it a numbered caption)::

    book.show_figure("WF-fig1")

and ends a section with its published-versus-reproduced rows::

    book.claims_table(prefix="WF-sec3")
"""

from __future__ import annotations

import html
import re
from pathlib import Path
from typing import Any

from navcore import figures as _figures
from navcore import ledger
from navcore.claims.declarations import STATUSES
from navcore.formatting import estimate_text, format_number, math_spans, number_formatter, tidy_numbers
from navcore.ledger import text as ledger_text
from navcore.ledger.interactive import InteractiveLedger
from navcore.ledger.summary import findings_phrase
from navcore.ledger.tables import CountsTable, ErrataList, FindingsTable, LedgerTable, latex_table

__all__ = [
    "Markdown",
    "assumptions_table",
    "book_root_prefix",
    "chapter_summary",
    "claims_table",
    "counts_table",
    "errata_list",
    "erratum_box",
    "estimate_text",
    "findings_table",
    "format_number",
    "glue",
    "item_key",
    "ledger_table",
    "number_formatter",
    "page_titles",
    "quantity_table",
    "select_claims",
    "setup",
    "show_figure",
    "table",
    "table_claims",
    "text_table",
]


def setup() -> None:
    """Inline PNG figures, the book's figure style, and compact numpy printing.

    In a notebook kernel this also gives pandas DataFrames and Stylers a Markdown
    representation next to their HTML, so that the PDF shows them as tables rather than as
    plain text. It selects matplotlib's inline backend (a kernel started with
    ``MPLBACKEND=Agg`` would otherwise show figures as ``<Figure size ...>`` text) with PNG
    output, which both the HTML and the LaTeX builders can use.

    Outside a kernel it applies the figure style (:func:`navcore.figures.apply_style`) and
    numpy's print options (5 digits, no scientific notation for small numbers, 100
    characters a line) only.

    Returns
    -------
    None
        The settings are global to the process.
    """
    import numpy as np

    try:
        from IPython import get_ipython
    except ImportError:  # pragma: no cover - plain Python
        get_ipython = None
    shell = get_ipython() if get_ipython is not None else None
    if shell is not None and hasattr(shell, "kernel"):
        shell.run_line_magic("matplotlib", "inline")
        from matplotlib_inline.backend_inline import set_matplotlib_formats

        set_matplotlib_formats("png")
        # pandas tables: a Markdown twin of their HTML, which the PDF builder renders as a table
        markdown = shell.display_formatter.formatters["text/markdown"]
        markdown.for_type_by_name("pandas.core.frame", "DataFrame", _markdown_table)
        markdown.for_type_by_name("pandas.io.formats.style", "Styler", _markdown_table)
        # and an HTML whose element ids do not change from run to run (pandas draws a random uuid)
        shell.display_formatter.formatters["text/html"].for_type_by_name(
            "pandas.io.formats.style", "Styler", _styler_html
        )
    _figures.apply_style()
    np.set_printoptions(precision=5, suppress=True, linewidth=100)


def book_root_prefix() -> str:
    """Relative link prefix from the executing page's folder to the book's root.

    The book executes every page in its own folder, so the folder holding ``_toc.yml`` above
    the working directory is the book's root: ``""`` for a top-level page, ``"../"`` for a
    chapter page. Outside a book checkout the chapter prefix ``"../"`` is returned.

    Returns
    -------
    str
        ``""``, ``"../"``, ``"../../"`` or ``"../../../"``: one ``"../"`` per folder between
        the working directory and the book's root (at most three are searched).

    Examples
    --------
    >>> book_root_prefix() in ("", "../", "../../", "../../../")
    True
    """
    here = Path.cwd().resolve()
    for depth, folder in enumerate([here, *here.parents][:4]):
        if (folder / "_toc.yml").exists():
            return "../" * depth
    return "../"


def item_key(item: str) -> str:
    """A printed item as the claims' locators name it (an equation by its number).

    Parameters
    ----------
    item : str
        One printed item in the paper's words: ``"Eq. (4.5.37)"``, ``"Table 4.3"``,
        ``"Fig. 2.1"``, ``"Sec. 4.5.4"``, ``"Appendix G"``, ``"Remark ii"``.

    Returns
    -------
    str
        Its key (:func:`navcore.traceability.items_in_text`): ``"4.5.37"``, ``"Table 4.3"``.

    Raises
    ------
    ValueError
        If the text names no item or more than one.

    Examples
    --------
    >>> item_key("Eq. (4.5.37)"), item_key("Table 4.3"), item_key("Sec. IV.D")
    ('4.5.37', 'Table 4.3', 'Sec. IV.D')
    """
    from navcore.traceability import items_in_text

    found = items_in_text(item, dotted=True)
    if len(found) != 1:
        raise ValueError(f"{item!r} names {len(found)} printed items, not one: {sorted(found)}")
    return found.pop()


def select_claims(paper: str | None, items: list[str]) -> list[str]:
    """The ids of the claims that check the given printed items of a paper.

    A claim checks an item when its locator names it (read by
    :func:`navcore.traceability.claim_refs`, as the traceability index reads it); a locator
    naming several items puts the claim under each. Nothing is evaluated.

    Parameters
    ----------
    paper : str or None
        Paper key (``"ATC10"``); items are numbered per paper.
    items : list of str
        Printed items (:func:`item_key`), in the order the table shows them.

    Returns
    -------
    list of str
        Claim ids: the first item's claims, then the next item's not yet listed, and so on;
        within an item in the ledger's order (:func:`navcore.ledger.claims`).

    Raises
    ------
    ValueError
        If ``paper`` is ``None`` or an item selects no claim of the paper.

    Examples
    --------
    >>> select_claims("KZL", ["Eq. (9)"])
    ['KZL-sec3.2-earth-transport-rates-negligible', 'KZL-eq9-quaternion']
    """
    from navcore.traceability import claim_refs

    if paper is None:
        raise ValueError("selecting claims by printed item needs the paper's key")
    by_item: dict[str, list[str]] = {}
    for c in ledger.claims(paper):
        for ref in claim_refs(c.locator, c.paper):
            by_item.setdefault(ref.item, []).append(c.id)
    out: list[str] = []
    for item in items:
        found = by_item.get(item_key(item))
        if not found:
            raise ValueError(f"no claim of {paper} names {item!r} in its locator")
        out += [i for i in found if i not in out]
    return out


def table_claims(paper: str | None, table: str) -> list[str]:
    """The ids of the claims of a paper that its page's table ``table`` shows.

    A claim that its locator's printed item does not place on a table names its table itself
    (:attr:`~navcore.claims.declarations.Claim.table`), so a page selects it by that name and a
    new claim joins a table with no change to the page. Nothing is evaluated.

    Parameters
    ----------
    paper : str or None
        Paper key (``"KZL"``); table names are the pages' own, and a page is one paper's.
    table : str
        The table's name (``"heading"``).

    Returns
    -------
    list of str
        The ids of the claims of ``paper`` whose ``table`` is ``table``, in the ledger's order
        (:func:`navcore.ledger.claims`: the paper modules' order of declaration).

    Raises
    ------
    ValueError
        If ``paper`` is ``None``, no claim of the paper names the table, or the claims that name
        it are discussed on more than one page (a table is one page's).

    Examples
    --------
    >>> table_claims("KZL", "no-such-table")
    Traceback (most recent call last):
    ...
    ValueError: table='no-such-table' selects no claim of KZL: no claim declares table='no-such-table'
    """
    if paper is None:
        raise ValueError(f"selecting claims by table (table={table!r}) needs the paper's key")
    found = [c for c in ledger.claims(paper) if c.table == table]
    if not found:
        raise ValueError(f"table={table!r} selects no claim of {paper}: no claim declares table={table!r}")
    pages = sorted({c.discussed_in for c in found})
    if len(pages) > 1:
        raise ValueError(f"table={table!r} of {paper} is named by claims of several pages: {pages}")
    return [c.id for c in found]


def claims_table(
    paper: str | None = None,
    prefix: str | None = None,
    ids: list[str] | None = None,
    *,
    items: list[str] | None = None,
    table: str | None = None,
    notes: bool = True,
    root: str | None = None,
    link_pages: bool = False,
) -> LedgerTable:
    """Published-versus-reproduced table of the selected claims (HTML coloured; PDF table).

    A section's table selects its claims by the printed items they check (``items``, see
    :func:`select_claims`), so that a new claim whose locator names one of them joins the
    table with no change to the page. A table that shows a part of an item's claims (a
    section's statements, one figure's bounds) has a name on its page, and its claims name it
    (:attr:`~navcore.claims.declarations.Claim.table`, :func:`table_claims`): a new claim joins
    it by its declaration alone. ``ids`` names claims one by one (in a notebook; the book's
    pages do not type claim ids).

    ``root`` is the link prefix to the book's root (default: found from the working
    directory, see :func:`book_root_prefix`); ``link_pages`` links each claim to the page
    that derives it (for the ledger page).

    Parameters
    ----------
    paper : str or None, optional
        Paper key of the claims to show (with ``prefix``, or with ``items`` or ``table``,
        which need it; ignored when only ``ids`` is given).
    prefix : str or None, optional
        Id prefix of the claims to show (``"WF-sec3"``).
    ids : list of str or None, optional
        The claims to show, in this order (ids or former ids); overrides ``prefix``. With
        ``items`` or ``table``, shown after their claims (those not shown already).
    items : list of str or None, optional
        Printed items of ``paper`` (``"Eq. (4.5.37)"``, ``"Table 4.3"``, ``"Sec. 4.6"``):
        every claim whose locator names one of them, in this order
        (:func:`select_claims`); overrides ``prefix``.
    table : str or None, optional
        The name of a table of the page: every claim of ``paper`` that names it
        (:func:`table_claims`), in the ledger's order; with ``items``, shown after the items'
        claims (those not shown already). Overrides ``prefix``.
    notes : bool, optional
        Show each claim's note, tolerance, band and inputs.
    root : str or None, optional
        Link prefix to the book's root; ``None`` finds it.
    link_pages : bool, optional
        Link each claim id to the page that derives it.

    Returns
    -------
    LedgerTable
        The table (:class:`~navcore.ledger.tables.LedgerTable`); the selected claims are
        evaluated (memoised, :func:`~navcore.ledger.registry.evaluate_claim`).

    Raises
    ------
    ValueError
        If no claim is selected, an id is not in the ledger, ``items`` or ``table`` is given
        without ``paper``, an item selects no claim, or ``table`` names no claim's table.

    Examples
    --------
    A real claim is evaluated when its table is made; here the evaluation is replaced by one
    of a synthetic claim:

    >>> from unittest import mock
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> with mock.patch("navcore.ledger.evaluate_claim", return_value=ev):
    ...     t = claims_table(ids=["SP-doc-omega"], root="../")
    >>> [g.heading for g in t.groups()], t.root
    (['Fig. 2.1'], '../')
    """
    if items is None and table is None and ids is not None:
        evals = [ledger.evaluate_claim(i) for i in ids]
    elif items is not None or table is not None:
        # the items' claims, then the table's not among them, then the typed ids not among them
        chosen = select_claims(paper, items) if items is not None else []
        if table is not None:
            chosen += [i for i in table_claims(paper, table) if i not in chosen]
        chosen += [i for i in ids or () if ledger.claim(i).id not in chosen]
        evals = [ledger.evaluate_claim(i) for i in chosen]
    else:
        evals = ledger.evaluations(paper=paper, prefix=prefix)
    if not evals:
        raise ValueError(f"no claims match paper={paper!r}, prefix={prefix!r}, ids={ids!r}")
    root = book_root_prefix() if root is None else root
    return LedgerTable(evals, show_notes=notes, root=root, link_pages=link_pages)


def counts_table(paper: str | None = None) -> CountsTable:
    """Counts of claims per paper and status.

    Every claim of the paper (of every paper, by default) is evaluated.

    Parameters
    ----------
    paper : str or None, optional
        Paper key; ``None`` for every paper (with a row of totals).

    Returns
    -------
    CountsTable
        The table (:class:`~navcore.ledger.tables.CountsTable`): per paper, the claims with
        each derived verdict, the total and the number failing their check.

    Examples
    --------
    With the evaluations replaced by the one of a synthetic claim (the real ones take
    minutes):

    >>> from unittest import mock
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> row = {"reproduced": 1, "consistent": 0, "inconsistent": 0, "discrepant": 0,
    ...        "not-reproducible": 0, "total": 1}
    >>> with mock.patch("navcore.ledger.tables.counts", return_value={"SP": row}):
    ...     with mock.patch("navcore.ledger.tables.evaluations", return_value=[ev]):
    ...         print(repr(counts_table("SP")))
    Paper  reproduced  consistent  inconsistent  discrepant  not-reproducible  total  failing check
    SP  1  0  0  0  0  1  0
    """
    return CountsTable(paper)


def errata_list(paper: str | None = None, *, root: str | None = None, caveat: bool = True) -> ErrataList:
    """The registered errata (of one paper, or all), linked to the pages that discuss them.

    Parameters
    ----------
    paper : str or None, optional
        Paper key; ``None`` for every paper's errata.
    root : str or None, optional
        Link prefix to the book's root (``None`` finds it, :func:`book_root_prefix`); the
        pages under it give the link texts (their titles).
    caveat : bool, optional
        Say the text-only caveat once, under the text-only heading (``False`` where the page
        says it already).

    Returns
    -------
    ErrataList
        The list (:class:`~navcore.ledger.tables.ErrataList`), one entry per erratum.

    Raises
    ------
    ValueError
        If ``paper`` is not a paper key.
    """
    root = book_root_prefix() if root is None else root
    return ErrataList(
        ledger.errata(paper),
        root=root,
        titles=page_titles(Path.cwd() / root),
        evals=ledger.evaluations(paper=paper),
        caveat=caveat,
    )


def erratum_box(erratum_id: str, page: str | None = None) -> tuple[str, list[list[tuple[str, str]]]]:
    """An erratum's box as the page that discusses it shows it, in the erratum's own words.

    The book's ``{erratum}`` directive builds its warning box from this, so that a page
    never writes an erratum's text by hand.

    Parameters
    ----------
    erratum_id : str
        The erratum's id (``"ATC10-E4.10-scalar-gain"``).
    page : str or None, optional
        The page (docname, ``"atc10/31-clock-tracking"``) that shows the box: it must be the
        erratum's ``discussed_in``; ``None`` does not check.

    Returns
    -------
    title : str
        ``"Erratum <id>"``.
    paragraphs : list of list of tuple of (str, str)
        What the paper prints (with the locator), what the book finds and the evidence, each a
        paragraph of ``(style, text)`` pieces, ``style`` one of ``"label"`` (a bold field
        name), ``"text"`` and ``"math"`` (the inside of a ``$...$`` span).

    Raises
    ------
    ValueError
        If no erratum has that id, or ``page`` is not the page that discusses it.

    Examples
    --------
    >>> first = ledger.errata("KZL")[0]
    >>> title, paragraphs = erratum_box(first.id, first.discussed_in)
    >>> title == f"Erratum {first.id}", [p[0] for p in paragraphs]
    (True, [('label', 'Printed'), ('label', 'The book finds:'), ('label', 'Evidence:')])
    >>> erratum_box("KZL-E1-levelling-sign", "wf/elsewhere")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ValueError: erratum 'KZL-E1-levelling-sign' is discussed in kzl/01-mechanization, not on wf/elsewhere: ...
    """
    e = ledger.erratum(erratum_id)
    if page is not None and e.discussed_in != page:
        raise ValueError(
            f"erratum {e.id!r} is discussed in {e.discussed_in or 'no page'}, not on {page}: "
            "show its box on that page, or set its discussed_in"
        )

    def pieces(text: str) -> list[tuple[str, str]]:
        return [("math" if is_math else "text", piece) for is_math, piece in math_spans(text)]

    paragraphs = [
        [("label", "Printed"), ("text", " ("), *pieces(e.locator), ("text", "): "), *pieces(e.printed)],
        [("label", "The book finds:"), ("text", " "), *pieces(e.finding)],
        [("label", "Evidence:"), ("text", " "), *pieces(e.evidence)],
    ]
    return f"Erratum {e.id}", paragraphs


def findings_table(
    paper: str | None = None, *, root: str | None = None, list_findings: bool = False
) -> FindingsTable:
    """The findings (errata) counted by paper, basis and kind, each with its claims as evidence.

    Every claim of the paper (of every paper, by default) is evaluated, to show the verdicts
    of the claims that are each finding's evidence.

    Parameters
    ----------
    paper : str or None, optional
        Paper key; ``None`` for every paper's findings (with rows of totals).
    root : str or None, optional
        Link prefix to the book's root; ``None`` finds it (:func:`book_root_prefix`).
    list_findings : bool, optional
        Also list every finding with its basis, kind and evidence.

    Returns
    -------
    FindingsTable
        The table (:class:`~navcore.ledger.tables.FindingsTable`); the text-only caveat
        follows the counts once.

    Raises
    ------
    ValueError
        If ``paper`` is not a paper key.

    Examples
    --------
    With the errata and evaluations replaced by synthetic ones (the real ones take minutes):

    >>> from unittest import mock
    >>> from navcore.ledger import Erratum
    >>> e = Erratum(id="SP-E9-doc", paper="SP", locator="Eq. (2.4.2)", printed="a + b",
    ...             finding="a - b", evidence="the derivation", kind="typography", basis="computed",
    ...             no_claim_reason="a synthetic erratum")
    >>> with mock.patch("navcore.ledger.errata", return_value=(e,)):
    ...     with mock.patch("navcore.ledger.evaluations", return_value=[]):
    ...         print(repr(findings_table("SP", root="")).splitlines()[1])
    SP  computed  1  0  0  0  0  0  0  1
    """
    root = book_root_prefix() if root is None else root
    return FindingsTable(
        ledger.errata(paper), ledger.evaluations(paper=paper), root=root, list_findings=list_findings
    )


def ledger_table(paper: str | None = None, *, root: str | None = None) -> InteractiveLedger:
    """Every claim (or one paper's) as one table that sorts, filters, searches and downloads.

    Parameters
    ----------
    paper : str or None, optional
        Paper key; ``None`` for every claim of the ledger.
    root : str or None, optional
        Link prefix to the book's root; ``None`` finds it (:func:`book_root_prefix`).

    Returns
    -------
    InteractiveLedger
        The table (:class:`~navcore.ledger.interactive.InteractiveLedger`); every selected claim
        is evaluated.

    Raises
    ------
    ValueError
        If ``paper`` is not a paper key.

    Examples
    --------
    With the evaluations replaced by the one of a synthetic claim (the real ones take
    minutes):

    >>> from unittest import mock
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> with mock.patch("navcore.ledger.evaluations", return_value=[ev]):
    ...     t = ledger_table("SP", root="")
    >>> [r["id"] for r in t.records]
    ['SP-doc-omega']
    """
    root = book_root_prefix() if root is None else root
    return InteractiveLedger(ledger.evaluations(paper=paper), root=root)


def page_titles(book_dir: Path) -> dict[str, str]:
    r"""Each page's title (its first level-1 heading), keyed by its path without suffix.

    Parameters
    ----------
    book_dir : Path
        The book's folder; every ``*.md`` below it is read.

    Returns
    -------
    dict of str to str
        ``{"sp/22-jammer-flyby": "The jammer flyby", ...}``; a page without a level-1
        heading is left out.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as d:
    ...     _ = (Path(d) / "wf").mkdir()
    ...     _ = (Path(d) / "wf" / "01-location.md").write_text("---\n---\n# Emitter location\n")
    ...     page_titles(Path(d))
    {'wf/01-location': 'Emitter location'}
    """
    titles = {}
    for page in sorted(book_dir.rglob("*.md")):
        for line in page.read_text(encoding="utf-8").splitlines():
            if line.startswith("# "):
                titles[page.relative_to(book_dir).with_suffix("").as_posix()] = line[2:].strip()
                break
    return titles


class Table:
    """A pandas table for both builders: the Styler's HTML, and a Markdown table for the PDF.

    A ``pandas.Styler`` (or a DataFrame) has no representation that the LaTeX builder can
    use (its plain-text fallback prints ``<pandas.io.formats.style.Styler at 0x...>``), so
    the chapters wrap their tables with :func:`table`.

    Every cell is shown as the Styler formats it, with program-style numbers tidied
    (:func:`~navcore.formatting.tidy_numbers`: ``9.40e-02`` reads ``9.40×10⁻²``, ``-0.00``
    reads ``0.00``), and an index or header of floats shows each value exactly (``60``, not
    ``60.000000``).

    Parameters
    ----------
    data : pandas.DataFrame or pandas.io.formats.style.Styler
        The table; a DataFrame is shown with its default style.

    Attributes
    ----------
    styler : pandas.io.formats.style.Styler
        The styled table both representations are made from.

    Examples
    --------
    >>> import pandas as pd
    >>> Table(pd.DataFrame({"paper": ["SP", "KZL"], "claims": [155, 48]})).cells()
    (['', 'paper', 'claims'], [['0', 'SP', '155'], ['1', 'KZL', '48']])
    """

    def __init__(self, data: Any) -> None:
        self.styler = data if hasattr(data, "to_html") and hasattr(data, "data") else data.style
        # an index or header of floats prints every value as it is (60, not 60.000000)
        for axis, labels in (("index", self.styler.data.index), ("columns", self.styler.data.columns)):
            if getattr(labels, "dtype", None) is not None and labels.dtype.kind == "f":
                self.styler.format_index(number_formatter("exact"), axis=axis)

    def _repr_html_(self) -> str:
        return _tidy_html(_styler_html(self.styler))

    def _repr_markdown_(self) -> str:
        """The printed table (a LaTeX longtable that fits the page; see ``latex_table``)."""
        head, body = self.cells()
        return latex_table(head, body)

    def __repr__(self) -> str:
        head, body = self.cells()
        return "\n".join("  ".join(row) for row in [head, *body])

    def cells(self) -> tuple[list[str], list[list[str]]]:
        """Heading and rows as the Styler formats them (index included unless hidden)."""
        sep = "\x1f"
        lines = [ln.split(sep) for ln in self.styler.to_string(delimiter=sep).splitlines() if ln.strip()]
        width = max(len(ln) for ln in lines)
        lines = [[tidy_numbers(c.strip()) for c in ln] + [""] * (width - len(ln)) for ln in lines]
        return lines[0], lines[1:]


def _tidy_html(table_html: str, *, math_breaks: bool = False) -> str:
    r"""The table's cell texts with numbers tidied (:func:`~navcore.formatting.tidy_numbers`)
    and ``$...$`` set as MathJax inline math, as in the claim rows; the style block before
    the table is left alone.

    With ``math_breaks`` (a table of text), a long formula may break across lines where TeX
    would break it in running text (:func:`~navcore.ledger.text.math_breaks`): its pieces are
    set one after the other, joined by a line-break opportunity (``<wbr>``).

    Examples
    --------
    >>> _tidy_html("<td>at $N_T$, 9.40e-02</td>")
    '<td>at <span class="math notranslate nohighlight">\\(N_T\\)</span>, 9.40×10⁻²</td>'
    >>> _tidy_html("<td>1/2 < $\\rho < 1$</td>")
    '<td>1/2 &lt; <span class="math notranslate nohighlight">\\(\\rho &lt; 1\\)</span></td>'
    >>> out = _tidy_html("<td>so $\\mathrm{Exp}_g = a^2/(2p)$</td>", math_breaks=True)
    >>> print(out.replace('<span class="math notranslate nohighlight">', "<span>"))
    <td>so <span>\(\mathrm{Exp}_g ={}\)</span><wbr><span>\(a^2/(2p)\)</span></td>
    """
    head, sep, body = table_html.rpartition("</style>")

    def cell(text: str) -> str:
        math = '<span class="math notranslate nohighlight">\\({}\\)</span>'

        def bare(piece: str) -> str:  # a "<" or ">" of the text itself, not markup
            return piece.replace("<", "&lt;").replace(">", "&gt;")

        def formula(tex: str) -> str:
            pieces = ledger_text.math_breaks(tex) if math_breaks else [tex]
            return "<wbr>".join(math.format(bare(piece)) for piece in pieces)

        pieces = math_spans(text)
        return "".join(formula(p) if is_math else bare(tidy_numbers(p)) for is_math, p in pieces)

    # text is whatever is not a tag: a "<" in a cell's text ("$\\rho < 1$") is text, not a tag
    parts = re.split(r"(<[A-Za-z/!][^<>]*>)", body)
    body = "".join(part if i % 2 else cell(part) for i, part in enumerate(parts))
    return head + sep + body


def _styler_html(styler: Any) -> str:
    """A Styler's HTML with an id derived from its content, so that two builds are identical."""
    import hashlib

    digest = hashlib.sha256(styler.data.to_csv().encode() + repr(styler.data.columns).encode())
    styler.set_uuid(digest.hexdigest()[:8])
    return styler.to_html()


def _markdown_table(data: Any) -> str:
    return Table(data)._repr_markdown_()


def table(data: Any) -> Table:
    """Show a DataFrame or a formatted ``df.style`` in the HTML and the PDF book alike.

    Parameters
    ----------
    data : pandas.DataFrame or pandas.io.formats.style.Styler
        The table (a Styler keeps its formats and hidden index).

    Returns
    -------
    Table
        The table for both builders (HTML from the Styler, the printed table for the PDF).

    Examples
    --------
    >>> import pandas as pd
    >>> print(repr(table(pd.DataFrame({"paper": ["SP", "KZL"], "claims": [155, 48]}))))
      paper  claims
    0  SP  155
    1  KZL  48
    """
    return Table(data)


def text_table(frame: Any, css_class: str | None = None) -> Table:
    """A DataFrame of mostly text (reasons, names) without its index, read left to right.

    Parameters
    ----------
    frame : pandas.DataFrame
        The table to show.
    css_class : str or None, optional
        A further HTML class for a table the book's style sheet lays out on its own (the
        verification reports' verdict counts and unresolved claims).

    Returns
    -------
    Table
        The table for both builders (HTML from the Styler, the printed table for the PDF).

    Examples
    --------
    >>> import pandas as pd
    >>> print(repr(text_table(pd.DataFrame({"paper": ["SP", "KZL"], "claims": [155, 48]}))))
    paper  claims
    SP  155
    KZL  48
    """
    styler = frame.style.hide(axis="index").set_properties(**{"text-align": "left"})
    if css_class is not None and not re.fullmatch(r"[A-Za-z][A-Za-z0-9_-]*", css_class):
        raise ValueError(f"text_table: css_class must be one HTML class name, got {css_class!r}")
    layout = _phone_layout(frame)
    classes = " ".join(c for c in ("navcore-text-table", layout, css_class) if c)
    styler = styler.set_table_attributes(f'class="{classes}"')  # its cells may break long words
    styler = styler.set_table_styles([{"selector": "th", "props": "text-align: left;"}])
    if layout == "navcore-cards":
        return _CardTable(styler, [str(c) for c in frame.columns])
    return _TextTable(styler)


#: A text table with at least this many columns is laid out for a phone (:func:`_phone_layout`).
_PHONE_COLUMNS = 4


def _phone_layout(frame: Any) -> str:
    """How a text table of four or more columns reads on a phone, as the class the style sheet
    lays it out by: ``navcore-counts-phone`` when every column after the first holds numbers
    (its headings turn upright on their side, so that the columns are as narrow as their
    numbers), ``navcore-cards`` when its headings are words (each row becomes a card whose
    fields are named by their headings), else ``""`` (a table as on a wide screen)."""
    if frame.shape[1] < _PHONE_COLUMNS or frame.empty:
        return ""

    def number(value: Any) -> bool:
        if isinstance(value, bool):
            return False
        if isinstance(value, int | float):
            return True
        return bool(re.fullmatch(r"[-−+]?[\d.,]+\s*%?", str(value).strip()))

    if all(number(v) for col in frame.columns[1:] for v in frame[col]):
        return "navcore-counts-phone"
    if any("$" in str(c) or not str(c).strip() for c in frame.columns):
        return ""  # a heading set as math (or none) cannot name a card's field
    return "navcore-cards"


class _TextTable(Table):
    """A table of text: a long formula in a cell may break where TeX would break it
    (:func:`~navcore.ledger.text.math_breaks`), so that its column is not as wide as the whole formula."""

    def _repr_html_(self) -> str:
        return _tidy_html(_styler_html(self.styler), math_breaks=True)


class _CardTable(_TextTable):
    """A text table whose body cells carry their column's heading (``data-label``), which the
    style sheet shows before each field when a phone lays the rows out as cards."""

    def __init__(self, data: Any, labels: list[str]) -> None:
        super().__init__(data)
        self.labels = labels

    def _repr_html_(self) -> str:
        def label(m: re.Match[str]) -> str:
            return f'{m.group(0)} data-label="{html.escape(self.labels[int(m.group(1))], quote=True)}"'

        return re.sub(r'<td [^>]*class="data row\d+ col(\d+)"', label, super()._repr_html_())


class Markdown:
    """An output with HTML and Markdown representations (for boxes and short notes).

    Parameters
    ----------
    markdown : str
        The Markdown (used by the PDF builder and as the plain text).
    html_text : str or None, optional
        The HTML; ``None`` lets the HTML builder use the Markdown.

    Attributes
    ----------
    markdown : str
        As given.
    html_text : str or None
        As given.

    Examples
    --------
    >>> box = Markdown("**Ledger for SP:** 3 claims", "<b>Ledger for SP:</b> 3 claims")
    >>> box
    **Ledger for SP:** 3 claims
    """

    def __init__(self, markdown: str, html_text: str | None = None) -> None:
        self.markdown = markdown
        self.html_text = html_text

    def _repr_markdown_(self) -> str:
        return self.markdown

    def _repr_html_(self) -> str | None:
        return self.html_text

    def __repr__(self) -> str:
        return self.markdown


def _claims_count(n: int) -> str:
    """``"1 claim"``, ``"46 claims"``."""
    return f"{n} claim{'' if n == 1 else 's'}"


def chapter_summary(paper: str) -> Markdown:
    """A box for the top of a chapter: its findings by basis and kind, then its claims by verdict.

    Every claim of the paper is evaluated.

    Parameters
    ----------
    paper : str
        Paper key (``"WF"``).

    Returns
    -------
    Markdown
        The findings (errata) counted by basis and kind, then the claims' counts by derived
        verdict, in a sentence (Markdown) and as coloured chips (HTML), with the number of
        claims failing their check, if any.

    Raises
    ------
    ValueError
        If ``paper`` is not a paper key.

    Examples
    --------
    With the evaluations and errata replaced by synthetic ones (the real ones take minutes):

    >>> from unittest import mock
    >>> from navcore.ledger import Claim, Erratum, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> e = Erratum(id="SP-E9-doc", paper="SP", locator="Eq. (2.4.2)", printed="a + b",
    ...             finding="a - b", evidence="the derivation", kind="typography", basis="text-only",
    ...             claims=("SP-doc-omega",))
    >>> ev = evaluate(c)
    >>> row = {"reproduced": 1, "consistent": 0, "inconsistent": 0, "discrepant": 0,
    ...        "not-reproducible": 0, "total": 1}
    >>> with mock.patch("navcore.ledger.counts", return_value={"SP": row}):
    ...     with mock.patch("navcore.ledger.evaluations", return_value=[ev]):
    ...         with mock.patch("navcore.ledger.errata", return_value=(e,)):
    ...             chapter_summary("SP")
    **Ledger for SP:** 1 finding: 1 text-only (1 typography). 1 claim — 1 reproduced; every check passes.
    """
    c = ledger.counts(paper)[paper]
    failing = sum(not e.passes for e in ledger.evaluations(paper))
    found = ledger.errata(paper)
    parts = [f"{c[s]} {s}" for s in STATUSES if c[s]]
    md = (
        f"**Ledger for {paper}:** {findings_phrase(found)}. {_claims_count(c['total'])} — "
        + ", ".join(parts)
        + (f"; **{failing} failing their check**" if failing else "; every check passes")
        + "."
    )
    chips = "".join(
        f'<span class="ledger-chip ledger-status-{html.escape(s)}">{c[s]} {html.escape(s)}</span>'
        for s in STATUSES
    )
    html_text = (
        f'<div class="ledger-summary"><b>Ledger for {paper}:</b> {html.escape(findings_phrase(found))}.'
        f"<br>{_claims_count(c['total'])} &nbsp; {chips}"
        + (f"<b class='ledger-failing'>{failing} failing</b>" if failing else "every check passes")
        + "</div>"
    )
    return Markdown(md, html_text)


def glue(name: str, variable: Any, display: bool = True) -> None:
    """Glue a value under ``name`` for ``{glue:}`` roles, as myst-nb's ``glue`` does, checked first.

    A number a page prints is either a claim's value or registered in :mod:`navcore.glued` with
    the function that computes it. For a registered name, the value is compared with what that
    function computes and refused if it differs, so the strict build fails rather than print a
    number no test reads.

    Parameters
    ----------
    name : str
        The glue name the page's ``{glue:text}`` roles use.
    variable : Any
        The value to glue.
    display : bool, default True
        Also show the value in the cell's output (myst-nb's default).

    Returns
    -------
    None
        The value is glued; nothing is returned.

    Raises
    ------
    ValueError
        If ``name`` is registered in :mod:`navcore.glued` and ``variable`` is not what its
        function computes.
    """
    from myst_nb import glue as _myst_glue

    from navcore import glued

    glued.check(name, variable)
    _myst_glue(name, variable, display=display)
    return None


def show_figure(fig_id: str, *, display: bool = False) -> Any:
    """Render a registered figure and glue it under ``fig_id`` for a ``{glue:figure}``.

    With ``display=True`` the figure is also shown in the cell output.

    Parameters
    ----------
    fig_id : str
        The registered figure's id (``"WF-fig1"``); the Markdown shows it with
        ``{glue:figure}`` under the same name.
    display : bool, optional
        Also show the figure in the cell's output.

    Returns
    -------
    None
        The figure is glued (and closed); nothing is returned.

    Raises
    ------
    ValueError
        If no figure has that id.
    """
    import matplotlib.pyplot as plt
    from myst_nb import glue

    fig = _figures.render(fig_id)
    glue(fig_id, fig, display=display)
    plt.close(fig)
    return None


_UNITS = {
    "m": "m",
    "km": "km",
    "mps": "m/s",
    "s": "s",
    "min": "min",
    "h": "h",
    "deg": "deg",
    "deg_s": "deg/s",
    "deg_h": "deg/h",
    "rad": "rad",
    "hz": "Hz",
    "dbw": "dBW",
    "dbw_hz": "dBW/Hz",
    "dbic": "dBic",
    "db": "dB",
    "dbhz": "dB-Hz",
    "ppm": "ppm",
    "ug": "µg",
    "g": "g",
    "nmi": "nmi",
    "nmi_h": "nmi/h",
    "w": "W",
    "mps2": "m/s²",
    "ft": "ft",
    "m2_s": "m²/s",
    "m2_s2": "m²/s²",
    "m2_s3": "m²/s³",
}


def _readable_name(name: str) -> str:
    """``cruise_altitude_m`` -> ``cruise altitude (m)``; text that is not a name is kept."""
    if " " in name or name != name.lower():
        return name
    parts = name.split("_")
    for n in (2, 1):
        unit = "_".join(parts[-n:])
        if len(parts) > n and unit in _UNITS:
            return " ".join(parts[:-n]) + f" ({_UNITS[unit]})"
    return " ".join(parts)


def _readable_value(value: Any) -> str:
    if isinstance(value, bool) or value is None:
        return {True: "yes", False: "no", None: "—"}[value]
    if isinstance(value, int | float):
        return format_number(value, "exact")
    if isinstance(value, tuple | list):
        return ", ".join(_readable_value(v) for v in value)
    return str(value)


def assumptions_table(rows: Any, head: tuple[str, str] = ("assumption", "value")) -> Table:
    """A two-column table of assumed inputs: readable names with units, compact numbers.

    Parameters
    ----------
    rows : iterable of (str, Any)
        Name and value pairs (``dict.items()`` of a scenario, say). A lower-case name with a
        unit suffix reads as words and a unit (``cruise_altitude_m`` -> "cruise altitude
        (m)"); other text is kept. Numbers are shown exactly as they are given
        (:func:`~navcore.formatting.format_number`, ``"exact"``: ``1×10⁹``, not ``1e+09``),
        truth values as yes/no, sequences comma-separated.
    head : tuple of (str, str), optional
        The two column headings.

    Returns
    -------
    Table
        The table without its index, for both builders.

    Examples
    --------
    >>> print(repr(assumptions_table([("cruise_altitude_m", 10000.0), ("dual_frequency", True)])))
    assumption  value
    cruise altitude (m)  10000
    dual frequency  yes
    """
    import pandas as pd

    data = pd.DataFrame([(_readable_name(str(k)), _readable_value(v)) for k, v in rows], columns=list(head))
    return Table(data.style.hide(axis="index"))


def quantity_table(rows: Any, head: tuple[str, str] = ("quantity", "value"), *, digits: int = 3) -> Table:
    """A few named computed values as a two-column table, each with ``digits`` significant digits.

    What a page would otherwise show as a printed dictionary (``{'error (deg)': 2.2914...}``).

    Parameters
    ----------
    rows : mapping or iterable of (str, Any)
        Names (with their units) and values; numbers are formatted with
        :func:`~navcore.formatting.format_number`, other values shown as they are.
    head : tuple of (str, str), optional
        The two column headings.
    digits : int, optional
        Significant digits of each number.

    Returns
    -------
    Table
        The table without its index, for both builders.

    Examples
    --------
    >>> print(repr(quantity_table({"attitude error (deg)": 2.2914, "residual (deg)": -0.0})))
    quantity  value
    attitude error (deg)  2.29
    residual (deg)  0
    """
    import pandas as pd

    items = rows.items() if hasattr(rows, "items") else rows
    data = pd.DataFrame(
        [(str(k), format_number(v, digits=digits) if not isinstance(v, str) else v) for k, v in items],
        columns=list(head),
    )
    styler = data.style.hide(axis="index").set_properties(subset=[head[0]], **{"text-align": "left"})
    return Table(styler)


class _HtmlLatexTable:
    """A table with its own HTML (cells already HTML) and the book's printed table."""

    def __init__(self, head: list[str], html_rows: list[list[str]], text_rows: list[list[str]]) -> None:
        self.head, self.html_rows, self.text_rows = head, html_rows, text_rows

    def _repr_html_(self) -> str:
        head = "".join(f"<th>{html.escape(h)}</th>" for h in self.head)
        body = "".join("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in self.html_rows)
        table = f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"
        return f'<div class="trace-table">{table}</div>'

    def _repr_markdown_(self) -> str:
        return latex_table(self.head, self.text_rows)

    def __repr__(self) -> str:
        return "\n".join("  ".join(row) for row in [self.head, *self.text_rows])


def trace_table(paper: str | None = None, index: Any = None, *, root: str | None = None) -> _HtmlLatexTable:
    """The traceability index of one paper (item, functions, tests, pages, claims), or with
    ``paper=None`` the reverse index (function, the items it implements).

    Pages are linked by their titles; the printed table lists one name per line.
    """
    from navcore import traceability

    index = index or traceability.build_index()
    root = book_root_prefix() if root is None else root
    titles = page_titles(Path.cwd() / root)

    def link(page: Any, displayed: bool) -> tuple[str, str]:
        title = re.sub(r"\s*\([^()]*\)$", "", titles.get(page.docname, page.title))  # no section list
        mark = "\u00a0★" if displayed else ""
        href = html.escape(f"{root}{page.docname}.html")
        return f'<a href="{href}">{html.escape(title)}</a>{mark}', title + mark

    if paper is None:
        head = ["navcore function", "Implements"]
        html_rows, text_rows = [], []
        for impl in index.implementations:
            name = f"{impl.module.removeprefix('navcore.')}.{impl.qualname}"
            refs = ", ".join(f"{r.paper} Eq. ({r.item})" if r.is_equation else str(r) for r in impl.refs)
            html_rows.append([f"<code>{html.escape(name)}</code>", html.escape(refs)])
            text_rows.append([name.replace(".", ".\u200b").replace("_", "_\u200b"), refs])
        return _HtmlLatexTable(head, html_rows, text_rows)

    from navcore import coverage

    # an equation without a claim says why it needs none (the coverage inventory's reason)
    reasons = {
        it.locator: it.reason
        for it in coverage.items(paper)
        if it.category == "equation" and not it.claims and it.reason
    }
    head = ["Item", "navcore", "Tests", "Book", "Claims"]
    html_rows, text_rows = [], []
    for e in index.by_paper(paper):
        item = f"Eq.\u00a0({e.ref.item})" if e.ref.is_equation else e.ref.item
        why = reasons.get(f"Eq. ({e.ref.item})", "") if (e.ref.is_equation and not e.claims) else ""
        funcs = [f.qualname for f in e.functions]
        tests = [t.removesuffix(".py") for t in sorted(e.tests)]
        pages = [link(p, True) for p in e.displayed_on] + [link(p, False) for p in e.mentioned_on]
        html_rows.append(
            [
                html.escape(item),
                "<br>".join(f"<code>{html.escape(f)}</code>" for f in funcs) or "—",
                "<br>".join(html.escape(t) for t in tests) or "—",
                "<br>".join(h for h, _ in pages) or "—",
                str(len(e.claims)) if e.claims else (f"none: {html.escape(why)}" if why else "—"),
            ]
        )
        text_rows.append(
            [
                item,
                "; ".join(f.replace("_", "_\u200b") for f in funcs) or "—",
                "; ".join(t.replace("_", "_\u200b") for t in tests) or "—",
                "; ".join(t for _, t in pages) or "—",
                str(len(e.claims)) if e.claims else ("none (Coverage)" if why else "—"),
            ]
        )
    return _HtmlLatexTable(head, html_rows, text_rows)
