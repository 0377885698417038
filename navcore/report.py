"""A verification report per paper: what was checked, what was found, on what it rests.

One self-contained document per paper (WF, SP, ATC10, KZL), generated from the ledger's
evaluations and the paper's registered items, errata, inputs and figures; no number in it is
typed in. It has six parts:

1. the build that computed it (:func:`navcore.provenance.build_provenance`): commit, state
   of the tree, the commit's date, the lock file's hash and the software's versions;
2. what was checked: the coverage of the paper's printed items (:mod:`navcore.coverage`);
3. the findings (errata) counted by basis and kind, each with its evidence and the claims
   that are its evidence (:func:`navcore.ledger.summary.finding_evidence`);
4. the claims counted by kind and verdict, with the inconsistent and not-reproducible ones
   listed with why;
5. the assumed inputs, fitted parameters and conventions, each with the claims that read it
   (:mod:`navcore.ledger.summary`);
6. the reproduced figures, each with the paper figure it redraws and the claims that check it.

:func:`build_report` assembles the report as a structured :class:`Report` (sections of
paragraphs, tables and findings); :func:`to_markdown`, :func:`to_latex` and :func:`to_text`
render it. The book's *Verification reports* pages show the same parts through the frame
functions below (:func:`coverage_frame`, :func:`unresolved_frame`, :func:`assumed_frame`,
...); ``python -m navcore report PAPER`` prints the findings in a terminal and
:func:`write_pdf` typesets the stand-alone PDF with XeLaTeX, strictly (a LaTeX error or an
overfull box fails it).

Examples
--------
>>> from navcore.ledger import Claim, evaluate, printed
>>> value, tol = printed("17.67")
>>> c = Claim(id="WF-doc-omega", paper="WF", locator="Fig. 1", quantity="natural frequency",
...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
...           expected_status="reproduced", note="a synthetic claim")
>>> r = build_report("WF", [evaluate(c)], errata=[])
>>> [s.key for s in r.sections]
['overview', 'coverage', 'findings', 'verdicts', 'inputs', 'figures']
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
import textwrap
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from navcore.claims.declarations import (
    ERRATUM_BASES,
    ERRATUM_KINDS,
    PAPERS,
    STATUSES,
    TEXT_ONLY_CAVEAT,
    Erratum,
)
from navcore.claims.evaluation import Evaluation
from navcore.ledger.summary import findings_phrase
from navcore.provenance import BuildProvenance, build_provenance, project_root

__all__ = [
    "FiguresTable",
    "FindingsBlock",
    "Report",
    "Section",
    "Table",
    "assumed_frame",
    "build_report",
    "check_paper",
    "conventions_frame",
    "coverage_frame",
    "figure_claims",
    "figures_frame",
    "figures_table",
    "findings_frame",
    "findings_phrase",
    "fitted_frame",
    "moved_claims",
    "overview_text",
    "to_latex",
    "to_markdown",
    "to_text",
    "unresolved_frame",
    "unresolved_notes",
    "verdicts_frame",
    "write_pdf",
    "write_reports",
]

#: The verdicts a report explains claim by claim (a discrepancy is explained by its finding).
UNRESOLVED = ("inconsistent", "not-reproducible")

#: How the book names each paper in its headings.
SHORT_TITLES = {
    "WF": "Wu and Fowler",
    "SP": "Schmidt and Phillips",
    "ATC10": "Lincoln Laboratory ATC-10",
    "KZL": "Knedlik, Zhou and Loffeld",
}

#: The paper's full reference, for the title page.
TITLES = {
    "WF": "N. E. Wu and M. L. Fowler, Application of MEMS for Improved Emitter Location Accuracy",
    "SP": "G. T. Schmidt and R. E. Phillips, INS/GPS Integration Architecture Performance "
    "Comparisons (NATO RTO-EN-SET-116)",
    "ATC10": "K. S. Schneider, I. G. Stiglitz and A. E. Eckberg, Surveillance Aspects of the "
    "Advanced Air Traffic Management System, MIT Lincoln Laboratory ATC-10 (1972)",
    "KZL": "S. Knedlik, J. Zhou and O. Loffeld, On Position and Attitude Estimation for Remote "
    "Sensing with Bistatic SAR (2009)",
}


def check_paper(paper: Any) -> str:
    """``paper`` if it is a paper key, else a ``ValueError`` naming the choices.

    Examples
    --------
    >>> check_paper("WF")
    'WF'
    >>> check_paper("XY")
    Traceback (most recent call last):
    ...
    ValueError: paper must be one of WF, SP, ATC10, KZL; got 'XY'
    """
    if not isinstance(paper, str) or paper not in PAPERS:
        raise ValueError(f"paper must be one of {', '.join(PAPERS)}; got {paper!r}")
    return paper


# ---------------------------------------------------------------------------------------
# the structured document


@dataclass(frozen=True)
class Table:
    """A table of text cells (``$...$`` is math); ``head`` names the columns."""

    head: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    ids: tuple[str, ...] = ()  # per row, the file a renderer may link its first cell to


@dataclass(frozen=True)
class FindingsBlock:
    """The findings listed one by one: basis, kind, printed text, finding, evidence, claims."""

    errata: tuple[Erratum, ...]
    status: dict[str, str] = field(default_factory=dict)  # claim id -> derived verdict


Block = str | Table | FindingsBlock


@dataclass(frozen=True)
class Section:
    """One part of a report: ``key`` names it, ``title`` heads it, ``blocks`` are its body
    (a ``str`` is a paragraph whose ``$...$`` is math)."""

    key: str
    title: str
    blocks: tuple[Block, ...]


@dataclass(frozen=True)
class Report:
    """A paper's verification report: its title, the build that computed it, its sections."""

    paper: str
    title: str
    reference: str
    provenance: BuildProvenance
    sections: tuple[Section, ...]

    def section(self, key: str) -> Section:
        """The section ``key`` (``"findings"``, ...); ``KeyError`` if there is none."""
        for s in self.sections:
            if s.key == key:
                return s
        raise KeyError(f"no section {key!r}; sections: {[s.key for s in self.sections]}")


def _frame_table(frame: Any) -> Table:
    return Table(
        tuple(str(c) for c in frame.columns),
        tuple(tuple(str(v) for v in row) for row in frame.itertuples(index=False)),
    )


# ---------------------------------------------------------------------------------------
# the parts, as frames the book shows and the stand-alone report prints


def findings_frame(errata: Sequence[Erratum]) -> Any:
    """The findings counted by kind (rows) and basis (columns), with the totals.

    One row per kind and a column per basis, so that the table is narrow and its headings stay
    whole words (kinds as columns broke "typo-graphy", "con-vention" in a text column).

    Returns
    -------
    pandas.DataFrame
        Columns ``Kind``, one per basis that has findings, and ``all``; one row per kind of
        :data:`~navcore.claims.declarations.ERRATUM_KINDS` and a last row ``all``, the counts of
        :func:`navcore.ledger.summary.findings_count_table`.

    Examples
    --------
    >>> findings_frame([]).columns.tolist()
    ['Kind', 'all']
    """
    import pandas as pd

    from navcore.ledger.summary import findings_count_table

    rows = [r for r in findings_count_table(errata) if r["paper"] != "all" or r["basis"] == "all"]
    by_basis = {("all" if r["paper"] == "all" else r["basis"]): r for r in rows}
    bases = [b for b in ERRATUM_BASES if b in by_basis] + ["all"]
    body = [
        {"Kind": k.replace("-", " "), **{b: int(by_basis[b][k]) if b in by_basis else 0 for b in bases}}
        for k in ERRATUM_KINDS
    ]
    body.append({"Kind": "all", **{b: int(by_basis[b]["total"]) if b in by_basis else 0 for b in bases}})
    return pd.DataFrame(body, columns=["Kind", *bases])


def _count_phrase(evals: Sequence[Evaluation]) -> str:
    parts = [f"{n} {s}" for s in STATUSES if (n := sum(e.status == s for e in evals))]
    other = sum(e.status not in STATUSES for e in evals)
    if other:
        parts.append(f"{other} whose evaluation failed")
    return f"{len(evals)} claim{'' if len(evals) == 1 else 's'}" + (": " + ", ".join(parts) if parts else "")


def overview_text(paper: str, evals: Sequence[Evaluation], errata: Sequence[Erratum]) -> str:
    """The report's opening paragraph: coverage, findings and verdicts in numbers.

    Parameters
    ----------
    paper : str
        Paper key.
    evals : sequence of Evaluation
        The paper's evaluations.
    errata : sequence of Erratum
        The paper's findings.

    Returns
    -------
    str
        One paragraph; every number in it is counted from its arguments or from the paper's
        registered items.
    """
    from navcore import coverage

    s = coverage.summary(paper)
    failing = sum(not e.passes for e in evals)
    checks = "every claim passes its own check" if not failing else f"{failing} claims fail their own check"
    covered = (
        f"Of the paper's {s['items']} printed numbers and checkable statements, {s['covered']} "
        f"({s['percent']:.0f} %) are checked by a claim; of its {s['equations']} numbered equations, "
        f"{s['equations_checked']} are checked by a claim."
        if s["items"]
        else "The paper's printed items are not inventoried."
    )
    return (
        f"{covered} The ledger holds {_count_phrase(evals)}; {checks}. "
        f"The book records {findings_phrase(errata)}."
    )


#: What the coverage table's last column holds beyond the items its counts count.
COVERAGE_NOTE = (
    "The last column lists every item of the section left without a claim: besides printed "
    "numbers, checkable statements and numbered equations, the inputs the paper gives and "
    "printed text with nothing to compute, which the counts do not include."
)


def coverage_frame(paper: str) -> Any:
    """Per section of the paper: printed items, those with a claim, equations, and what is left.

    Returns
    -------
    pandas.DataFrame
        :func:`navcore.coverage.sections_frame` of ``paper``, each item left written "item —
        reason" (a reason in parentheses after an item would nest the reason's own).
    """
    from navcore import coverage

    frame = coverage.sections_frame(check_paper(paper))
    left = [
        "; ".join(f"{i.printed} \u2014 {i.reason}" for i in r["left"]) or "—"
        for r in coverage.section_rows(paper)
    ]
    column = frame.columns[-1]
    if len(left) == len(frame):
        frame[column] = left
    return frame


def verdicts_frame(evals: Sequence[Evaluation]) -> Any:
    """The claims counted by kind and derived verdict (one paper: no paper column).

    Returns
    -------
    pandas.DataFrame
        :func:`navcore.ledger.summary.kind_counts_frame` without the ``Paper`` column.

    Examples
    --------
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="WF-doc-omega", paper="WF", locator="Fig. 1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> verdicts_frame([evaluate(c)])[["Kind", "reproduced", "Total"]].values.tolist()
    [['reproduction', 1, 1], ['all', 1, 1]]
    """
    from navcore.ledger.summary import kind_counts_frame

    return kind_counts_frame(evals).drop(columns="Paper")


def _shared_notes(evals: Sequence[Evaluation]) -> dict[str, tuple[str, list[str]]]:
    """The notes that two or more unsettled claims share: note -> (its letter, the claims' ids)."""
    by_note: dict[str, list[str]] = {}
    for e in evals:
        if e.status in UNRESOLVED and e.claim.note:
            by_note.setdefault(e.claim.note, []).append(e.claim.id)
    shared = [(note, ids) for note, ids in by_note.items() if len(ids) > 1]
    letters = [chr(ord("A") + i) if i < 26 else f"A{i - 25}" for i in range(len(shared))]
    return {note: (letter, ids) for letter, (note, ids) in zip(letters, shared, strict=True)}


def unresolved_notes(evals: Sequence[Evaluation]) -> list[str]:
    """The notes that two or more of :func:`unresolved_frame`'s claims share, each said once.

    Returns
    -------
    list of str
        One paragraph per shared note: its letter (the ``Why`` cell of each of its claims
        names it), the claims it is for and the note.
    """
    return [
        f"**Note {letter}**, for these {len(ids)} claims ({_ids(ids)}): {note}"
        for note, (letter, ids) in _shared_notes(evals).items()
    ]


def unresolved_frame(evals: Sequence[Evaluation]) -> Any:
    """The inconsistent and not-reproducible claims, each with what was printed and computed, and why.

    Returns
    -------
    pandas.DataFrame
        Columns ``Claim``, ``Verdict``, ``Where``, ``Printed``, ``Computed`` (the value at the
        nominal inputs, and the band over the assumed inputs' ranges when one was run) and
        ``Why`` (the claim's note, and the readings that agree when only others do). A note
        that several of these claims share is said once (:func:`unresolved_notes`); their
        ``Why`` cells name it ("See note A.").
    """
    import pandas as pd

    from navcore.ledger.text import (
        _agreeing_reading_text,
        _band_text,
        _printed_text,
        _reproduced_text,
        quote_text,
    )

    shared = _shared_notes(evals)
    rows = []
    for e in evals:
        if e.status not in UNRESOLVED:
            continue
        computed = _reproduced_text(e)
        band = _band_text(e)
        if band:
            computed += f"; band {band}"
        note = e.claim.note
        why = f"See note {shared[note][0]}." if note in shared else note
        agreeing = _agreeing_reading_text(e)
        if agreeing:
            why = f"{why.rstrip('.')}; {agreeing}." if why else agreeing
        rows.append(
            {
                "Claim": e.claim.id,
                "Verdict": e.status,
                "Where": e.claim.locator,
                # the report's tables print Markdown as text: the quote as the paper printed it
                "Printed": quote_text(_printed_text(e, mark=False)),
                "Computed": computed,
                "Why": why,
            }
        )
    return pd.DataFrame(rows, columns=["Claim", "Verdict", "Where", "Printed", "Computed", "Why"])


def _ids(ids: Sequence[str]) -> str:
    """Claim ids, those that differ only after their last dash written once with their endings.

    Examples
    --------
    >>> _ids(["SP-t2-a", "SP-t2-b", "SP-x"])
    'SP-t2-(a, b), SP-x'
    """
    groups: dict[str, list[str]] = {}
    for cid in ids:
        stem, _, end = cid.rpartition("-")
        groups.setdefault(stem, []).append(end)
    return ", ".join(
        f"{stem}-{ends[0]}" if len(ends) == 1 else f"{stem}-({', '.join(ends)})"
        for stem, ends in groups.items()
    )


#: A cell of claim ids longer than this (characters) names only their number; the ids follow the
#: table (:func:`moved_claims`), so that no row of a printed table outgrows a page.
MAX_IDS_CELL = 160


def _ids_cell(ids: Sequence[str]) -> str:
    """The claim ids of a table cell, or their number when the list is long (listed after the table).

    Examples
    --------
    >>> _ids_cell(["SP-t2-a", "SP-t2-b"])
    'SP-t2-(a, b)'
    >>> _ids_cell([f"SP-claim-{i}-number" for i in range(20)])
    '20 claims, listed after the table'
    """
    text = _ids(ids)
    return text if len(text) <= MAX_IDS_CELL else f"{len(ids)} claims, listed after the table"


def _readers(evals: Sequence[Evaluation], provenance: str) -> list[tuple[Any, list[str]]]:
    from navcore.ledger.summary import input_readers

    return input_readers(evals, provenance)


def moved_claims(evals: Sequence[Evaluation], provenance: str) -> list[str]:
    """The long claim lists of an inputs table, one paragraph per input, to follow the table.

    Parameters
    ----------
    evals : sequence of Evaluation
        The paper's evaluations.
    provenance : str
        ``"assumed"``, ``"fitted"`` or ``"convention"``.

    Returns
    -------
    list of str
        For each input whose cell in :func:`assumed_frame`, :func:`fitted_frame` or
        :func:`conventions_frame` gives only a number of claims: its name (as the table's
        first column gives it), the number and every claim id.
    """
    frames = {"assumed": assumed_frame, "fitted": fitted_frame, "convention": conventions_frame}
    frame = frames[provenance](evals)
    out = []
    for name, (_, ids) in zip(frame.iloc[:, 0], _readers(evals, provenance), strict=True):
        if len(_ids(ids)) > MAX_IDS_CELL:
            out.append(f"**{name}** ({len(ids)} claims): {_ids(ids)}.")
    return out


def _no_double_parentheses(text: str) -> str:
    """``"label ((6, 4, 55, 15))"`` -> ``"label (6, 4, 55, 15)"``: a tuple shown in parentheses
    keeps one pair."""
    return re.sub(r"\(\(([^()]*)\)\)", r"(\1)", text) if isinstance(text, str) else text


def assumed_frame(evals: Sequence[Evaluation]) -> Any:
    """The assumed inputs the claims read: nominal, range, reason, and the claims each moves.

    Returns
    -------
    pandas.DataFrame
        :func:`navcore.ledger.summary.assumed_inputs_frame` with the ids of the claims that
        read each input (column ``Claims it moves``) in place of their number; a long list
        gives only its number and follows the table (:func:`moved_claims`).
    """
    from navcore.ledger.summary import assumed_inputs_frame

    frame = assumed_inputs_frame(evals).drop(columns="Paper")
    frame["Claims"] = [_ids_cell(ids) for _, ids in _readers(evals, "assumed")]
    return frame.rename(columns={"Claims": "Claims it moves"}).map(_no_double_parentheses)


def fitted_frame(evals: Sequence[Evaluation]) -> Any:
    """The fitted parameters: value, the claims each was fitted to, and the claims that read it.

    Returns
    -------
    pandas.DataFrame
        :func:`navcore.ledger.summary.fitted_inputs_frame` with the ids of the claims that
        read each parameter (column ``Read by``) in place of their number; a long list gives
        only its number and follows the table (:func:`moved_claims`).
    """
    from navcore.ledger.summary import fitted_inputs_frame

    frame = fitted_inputs_frame(evals).drop(columns="Paper")
    frame["Claims reading it"] = [_ids_cell(ids) for _, ids in _readers(evals, "fitted")]
    return frame.rename(columns={"Claims reading it": "Read by"}).map(_no_double_parentheses)


def conventions_frame(evals: Sequence[Evaluation]) -> Any:
    """The conventions: the reading used, the others, and the claims each reading decides.

    Returns
    -------
    pandas.DataFrame
        :func:`navcore.ledger.summary.convention_inputs_frame` with the ids of the claims
        that read each convention (column ``Claims it moves``) in place of their number; a
        long list gives only its number and follows the table (:func:`moved_claims`).
    """
    from navcore.ledger.summary import convention_inputs_frame

    frame = convention_inputs_frame(evals).drop(columns="Paper")
    frame["Claims"] = [_ids_cell(ids) for _, ids in _readers(evals, "convention")]
    return frame.rename(columns={"Claims": "Claims it moves"}).map(_no_double_parentheses)


_FIG_REF = re.compile(r"\bFigs?\.\s+(\d+(?:\.\d+)*)(?:\s*(?:-|–|to|and)\s*(\d+(?:\.\d+)*))?")


def _figure_numbers(text: str) -> set[str]:
    """The figure numbers a locator names: ``"Figs. 3.3-3.6"`` -> {3.3, 3.4, 3.5, 3.6}.

    Examples
    --------
    >>> sorted(_figure_numbers("Figs. 3.3-3.6, text"))
    ['3.3', '3.4', '3.5', '3.6']
    >>> sorted(_figure_numbers("Fig. 2 and Table 1")), sorted(_figure_numbers("Fig. 2.1"))
    (['2'], ['2.1'])
    """
    out: set[str] = set()
    for m in _FIG_REF.finditer(text):
        first, last = m.group(1), m.group(2)
        out.add(first)
        if last:
            out.add(last)
            a, b = first.rsplit(".", 1) if "." in first else ("", first)
            c, d = last.rsplit(".", 1) if "." in last else ("", last)
            if a == c and b.isdigit() and d.isdigit():
                out.update(f"{a}.{n}" if a else str(n) for n in range(int(b), int(d) + 1))
    return out


def figure_claims(reproduces: str, evals: Sequence[Evaluation]) -> list[Evaluation]:
    """The claims among ``evals`` whose locator names a figure that ``reproduces`` names.

    Examples
    --------
    >>> figure_claims("new", [])
    []
    """
    wanted = _figure_numbers(reproduces)
    if not wanted:
        return []
    return [e for e in evals if wanted & _figure_numbers(e.claim.locator)]


_GLUE_FIGURE = re.compile(r"^```\{glue:figure\}\s+(\S+)\s*\n(?::name:\s*(\S+))?", re.M)


def _figure_pages(book_dir: Path) -> dict[str, tuple[str, str]]:
    """Each figure id the book shows -> (page docname, the figure's anchor or "")."""
    out: dict[str, tuple[str, str]] = {}
    if not book_dir.is_dir():
        return out
    for page in sorted(book_dir.rglob("*.md")):
        if "_build" in page.parts or page.name.startswith("_"):
            continue
        text = page.read_text(encoding="utf-8")
        for m in _GLUE_FIGURE.finditer(text):
            out.setdefault(
                m.group(1), (page.relative_to(book_dir).with_suffix("").as_posix(), m.group(2) or "")
            )
    return out


#: A figure name that carries the paper's figure number (book/_ext/book_presentation.py, which
#: numbers the book's figures: the paper's number where a figure redraws one, else N1, N2, ...
#: per chapter in the order of its pages).
_PAPER_FIGURE_NAME = re.compile(r"^fig-(?:wf|sp|atc10|kzl)-(?:fig)?\d+(?:-\d+)*(?:-to-\d+(?:-\d+)*)?$")


def _own_figure_numbers(book_dir: Path, paper: str) -> dict[str, str]:
    """Each figure of the book's own in ``paper``'s chapter -> its number there ("N1", ...).

    The chapter's pages are its index and then its numbered pages in name order (the book's
    table of contents globs them so); within a page, its figures in order.
    """
    folder = book_dir / paper.lower()
    if not folder.is_dir():
        return {}
    pages = [folder / "index.md", *sorted(folder.glob("[0-9]*.md"))]
    out: dict[str, str] = {}
    for page in pages:
        if not page.is_file():
            continue
        for m in _GLUE_FIGURE.finditer(page.read_text(encoding="utf-8")):
            name = m.group(2)
            if name and not _PAPER_FIGURE_NAME.match(name):
                out.setdefault(m.group(1), f"N{len(out) + 1}")
    return out


def _page_titles(book_dir: Path) -> dict[str, str]:
    if not book_dir.is_dir():
        return {}
    from navcore.book import page_titles

    return page_titles(book_dir)


def figures_frame(paper: str, evals: Sequence[Evaluation], book_dir: Path | None = None) -> Any:
    """The paper's reproduced figures: what each redraws, the claims that check it, where it is shown.

    The paper's own figures are not available as images; each reproduced figure is named with
    the paper figure it redraws, so a reader can set the two side by side.

    Parameters
    ----------
    paper : str
        Paper key.
    evals : sequence of Evaluation
        The paper's evaluations (the claims that check a figure are among them).
    book_dir : path, optional
        The book's folder, to name the page that shows each figure (default: the checkout's
        ``book``; pages are not named when it is absent).

    Returns
    -------
    pandas.DataFrame
        Columns ``Figure`` (the figure as the book numbers it: the paper's number, or N1, N2,
        ... for a figure of the book's own; its id when the book is absent), ``Redraws`` (the
        paper's figure, or "not in the paper"), ``Claims that check it`` (id and verdict),
        ``Shown in`` (the page's title) and, hidden from the tables, ``page``, ``anchor``
        (for links) and ``id`` (the figure's file name).
    """
    import pandas as pd

    from navcore import figures

    check_paper(paper)
    book_dir = project_root() / "book" if book_dir is None else Path(book_dir)
    shown = _figure_pages(book_dir)
    titles = _page_titles(book_dir)
    own = _own_figure_numbers(book_dir, paper)
    rows = []
    specs = [s for s in figures.registry().values() if s.paper == paper]
    specs.sort(key=lambda s: (s.reproduces == "new", _fig_key(s.reproduces), s.id))
    for s in specs:
        checks = figure_claims(s.reproduces, evals)
        page, anchor = shown.get(s.id, ("", ""))
        if s.reproduces != "new":
            number = s.reproduces if s.id in shown or not shown else s.id
        else:
            number = f"Fig. {own[s.id]}" if s.id in own else s.id
        rows.append(
            {
                "Figure": number,
                "Redraws": "not in the paper" if s.reproduces == "new" else s.reproduces,
                "Claims that check it": ", ".join(f"{e.claim.id} ({e.status})" for e in checks)
                or "no claim names it",
                "Shown in": titles.get(page, ""),
                "page": page,
                "anchor": anchor,
                "id": s.id,
            }
        )
    columns = ["Figure", "Redraws", "Claims that check it", "Shown in", "page", "anchor", "id"]
    return pd.DataFrame(rows, columns=columns)


class FiguresTable:
    """The figures table for the book: each figure's page linked in HTML, named in print.

    Parameters
    ----------
    frame : pandas.DataFrame
        :func:`figures_frame`'s rows (with its ``page`` and ``anchor`` columns).
    root : str
        Link prefix from the showing page to the book's root.
    """

    def __init__(self, frame: Any, root: str) -> None:
        import html

        self.plain = frame.drop(columns=["page", "anchor", "id"])
        linked = self.plain.copy()
        shown = []
        for page, anchor, title in zip(frame["page"], frame["anchor"], frame["Shown in"], strict=True):
            if not page:
                shown.append(html.escape(title))
                continue
            href = f"{root}{page}.html" + (f"#{anchor}" if anchor else "")
            shown.append(f'<a href="{html.escape(href)}">{html.escape(title)}</a>')
        linked["Shown in"] = shown
        self.linked = linked

    def _repr_html_(self) -> str:
        from navcore.book import text_table

        return text_table(self.linked)._repr_html_()

    def _repr_markdown_(self) -> str:
        from navcore.book import text_table

        return text_table(self.plain)._repr_markdown_()

    def __repr__(self) -> str:
        return self.plain.to_string(index=False)


def figures_table(paper: str, evals: Sequence[Evaluation], root: str | None = None) -> FiguresTable:
    """:func:`figures_frame` for a book page: each figure linked to where its page shows it.

    Parameters
    ----------
    paper : str
        Paper key.
    evals : sequence of Evaluation
        The paper's evaluations.
    root : str, optional
        Link prefix to the book's root (default: found from the working directory,
        :func:`navcore.book.book_root_prefix`).

    Returns
    -------
    FiguresTable
        HTML with links, and the printed table for the PDF.
    """
    from navcore.book import book_root_prefix

    root = book_root_prefix() if root is None else root
    here = Path.cwd() / root
    return FiguresTable(figures_frame(paper, evals, here if (here / "_toc.yml").exists() else None), root)


def _fig_key(reproduces: str) -> tuple[int, ...]:
    nums = re.findall(r"\d+", reproduces)
    return tuple(int(n) for n in nums)


# ---------------------------------------------------------------------------------------
# the report


def build_report(
    paper: str,
    evals: Sequence[Evaluation] | None = None,
    *,
    errata: Sequence[Erratum] | None = None,
    provenance: BuildProvenance | None = None,
    book_dir: Path | None = None,
) -> Report:
    """The verification report of ``paper``, from the ledger's evaluations and its registrations.

    Parameters
    ----------
    paper : str
        Paper key, one of :data:`~navcore.claims.declarations.PAPERS`.
    evals : sequence of Evaluation, optional
        The paper's evaluations; ``None`` evaluates them through the ledger (and its on-disk
        cache, :func:`~navcore.ledger.registry.cache_dir`).
    errata : sequence of Erratum, optional
        The paper's findings; ``None`` for its registered errata.
    provenance : BuildProvenance, optional
        What built the report; ``None`` for this checkout's
        (:func:`~navcore.provenance.build_provenance`).
    book_dir : path, optional
        The book's folder, to name the pages that show the figures.

    Returns
    -------
    Report
        Sections ``overview``, ``coverage``, ``findings``, ``verdicts``, ``inputs`` and
        ``figures``.

    Raises
    ------
    ValueError
        If ``paper`` is not a paper key.
    """
    from navcore import ledger

    check_paper(paper)
    evals = list(ledger.evaluations(paper) if evals is None else evals)
    errata = list(ledger.errata(paper) if errata is None else errata)
    provenance = build_provenance() if provenance is None else provenance
    sections = []

    sections.append(Section("overview", "Summary", (overview_text(paper, evals, errata),)))

    cov = coverage_frame(paper)
    cov_blocks: list[Block] = [
        "Each section of the paper with its printed numbers and checkable statements, how many "
        "of them a claim of the ledger checks, its numbered equations and how many a claim checks, "
        "and every item left without a claim, with the reason."
    ]
    if len(cov):
        cov_blocks += [_frame_table(cov), COVERAGE_NOTE]
    else:
        cov_blocks.append("The paper's printed items are not inventoried.")
    sections.append(Section("coverage", "What was checked", tuple(cov_blocks)))

    f_blocks: list[Block] = [findings_phrase(errata) + "."]
    if errata:
        f_blocks.append(_frame_table(findings_frame(errata)))
        if any(e.basis == "text-only" for e in errata):
            f_blocks.append(TEXT_ONLY_CAVEAT)
        status = {e.claim.id: e.status for e in evals}
        f_blocks.append(FindingsBlock(tuple(errata), status))
    sections.append(Section("findings", "Findings", tuple(f_blocks)))

    v_blocks: list[Block] = [
        _count_phrase(evals) + ", by kind and derived verdict.",
        _frame_table(verdicts_frame(evals)),
    ]
    unresolved = unresolved_frame(evals)
    if len(unresolved):
        v_blocks.append(
            "The claims the ledger could not settle: inconsistent (the printed value lies outside "
            "everything the assumed inputs allow) or not reproducible (the band the assumptions "
            "span is too wide to decide, the search over more than six assumed inputs cannot rule "
            "the printed value out, or nothing could be computed), each with why."
        )
        notes = unresolved_notes(evals)
        if notes:
            v_blocks.append("Notes that several of these claims share are given once, before the table:")
            v_blocks += notes
        v_blocks.append(_frame_table(unresolved))
    else:
        v_blocks.append("No claim of this paper is inconsistent or not reproducible.")
    sections.append(Section("verdicts", "Claims by verdict", tuple(v_blocks)))

    i_blocks: list[Block] = []
    for title, frame, kind in (
        ("Assumed inputs (not in the paper: nominal value, plausible range and reason), each with the "
         "claims whose computation reads it.", assumed_frame(evals), "assumed"),
        ("Fitted parameters (solved from printed results, which are then not evidence), each with "
         "the claims it was fitted to and the claims that read it.", fitted_frame(evals), "fitted"),
        ("Conventions (readings the text leaves open; every claim that reads one is evaluated under "
         "each reading), each with the claims it moves.", conventions_frame(evals), "convention"),
    ):  # fmt: skip
        if len(frame):
            i_blocks += [title, _frame_table(frame)]
            lists = moved_claims(evals, kind)
            if lists:
                i_blocks += ["The claims of the longer lists:", *lists]
    if not i_blocks:
        i_blocks.append("No claim of this paper reads an assumed, fitted or convention input.")
    sections.append(Section("inputs", "Assumptions and fits", tuple(i_blocks)))

    figs = figures_frame(paper, evals, book_dir)
    g_blocks: list[Block] = [
        "The paper's figures are not reproduced here as images; each figure the book redraws is "
        "listed with the paper figure it redraws, the claims that check it, and the page of the "
        "book that shows it, numbered as the book numbers it (the paper's number, or N1, N2, ... "
        "for a figure that is not in the paper)."
    ]
    if len(figs):
        table = _frame_table(figs.drop(columns=["page", "anchor", "id"]))
        g_blocks.append(Table(table.head, table.rows, tuple(figs["id"])))
    else:
        g_blocks.append("The book redraws no figure of this paper.")
    sections.append(Section("figures", "Figures", tuple(g_blocks)))

    return Report(
        paper=paper,
        title=f"Verification report: {SHORT_TITLES[paper]}",
        reference=TITLES[paper],
        provenance=provenance,
        sections=tuple(sections),
    )


# ---------------------------------------------------------------------------------------
# renderers


def _claims_line(e: Erratum, status: dict[str, str]) -> str:
    return ", ".join(f"{c} ({status[c]})" if c in status else c for c in e.claims) or (
        "none" + (f": {e.no_claim_reason}" if getattr(e, "no_claim_reason", "") else "")
    )


def _md_cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def to_markdown(report: Report, figures_href: str | None = None) -> str:
    """The report as Markdown (``$...$`` math, pipe tables), for a reader or a converter.

    ``figures_href``, the folder of the reproduced figures relative to where the Markdown is
    written, links each figure id to its PNG (no links when ``None``).

    Examples
    --------
    >>> r = Report("WF", "Verification report: WF", "a paper", build_provenance(),
    ...            (Section("overview", "Summary", ("One paragraph.",)),))
    >>> to_markdown(r).splitlines()[0]
    '# Verification report: WF'
    """
    out = [f"# {report.title}", "", f"*{report.reference}*", "", "## Build", ""]
    out += ["| Built with | Value |", "| --- | --- |"]
    out += [  # hashes and versions as code, words as text
        f"| {_md_cell(w)} | {_md_cell(v) if ' ' in v else f'`{_md_cell(v)}`'} |"
        for w, v in report.provenance.rows()
    ]
    for s in report.sections:
        out += ["", f"## {s.title}", ""]
        for b in s.blocks:
            if isinstance(b, str):
                out += [b, ""]
            elif isinstance(b, Table):
                out.append("| " + " | ".join(_md_cell(h) for h in b.head) + " |")
                out.append("| " + " | ".join("---" for _ in b.head) + " |")
                for k, row in enumerate(b.rows):
                    cells = [_md_cell(c) for c in row]
                    if b.ids and figures_href is not None:  # the reproduced figure's image
                        cells[0] = f"[{cells[0]}]({figures_href}/{b.ids[k]}.png)"
                    out.append("| " + " | ".join(cells) + " |")
                out.append("")
            else:
                for e in b.errata:
                    out += [
                        f"### {e.id}: {e.locator}",
                        "",
                        f"- **Basis:** {e.basis}; **kind:** {e.kind}",
                        f"- **Printed:** {e.printed}",
                        f"- **The book finds:** {e.finding}",
                        f"- **Evidence:** {e.evidence}",
                        f"- **Claims (its evidence in the ledger):** {_claims_line(e, b.status)}",
                        "",
                    ]
    return "\n".join(out).rstrip() + "\n"


def _wrap(text: str, width: int, indent: str = "") -> list[str]:
    return textwrap.wrap(text, width, initial_indent=indent, subsequent_indent=indent) or [indent]


def _text_table(t: Table, width: int) -> list[str]:
    from navcore.ledger.summary import KIND_SHORT

    widths = [max(len(h), *(len(r[j]) for r in t.rows)) for j, h in enumerate(t.head)]
    if sum(widths) + 2 * len(widths) > width:  # the erratum kinds' short names (the ledger's)
        short = {k.replace("-", " "): v for k, v in KIND_SHORT.items()}
        t = Table(tuple(short.get(h, h) for h in t.head), t.rows)
        widths = [max(len(h), *(len(r[j]) for r in t.rows)) for j, h in enumerate(t.head)]
    if sum(widths) + 2 * len(widths) > width:  # too wide for a grid: one record per row
        out = []
        for row in t.rows:
            for j, (h, c) in enumerate(zip(t.head, row, strict=True)):
                out += _wrap(f"{h}: {c}", width, "  " if j else "")
            out.append("")
        return out
    lines = ["  ".join(h.ljust(w) for h, w in zip(t.head, widths, strict=True)).rstrip()]
    lines += ["  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)).rstrip() for row in t.rows]
    return lines


def to_text(section: Section, width: int = 100) -> str:
    """One section for a terminal: plain text, at most ``width`` columns (math as written).

    Examples
    --------
    >>> print(to_text(Section("x", "Findings", ("0 findings.",))))
    Findings
    ========
    0 findings.
    """
    out = [section.title, "=" * len(section.title)]
    for b in section.blocks:
        if isinstance(b, str):
            out += _wrap(b.replace("**", ""), width)
        elif isinstance(b, Table):
            out += _text_table(b, width)
        else:
            for basis in ERRATUM_BASES:
                sel = [e for e in b.errata if e.basis == basis]
                if not sel:
                    continue
                out += ["", f"{basis} findings ({len(sel)})", "-" * (len(basis) + 13 + len(str(len(sel))))]
                for e in sel:
                    out += ["", *_wrap(f"{e.id} ({e.kind}; {e.locator})", width)]
                    for label, text in (
                        ("printed", e.printed),
                        ("the book finds", e.finding),
                        ("evidence", e.evidence),
                        ("claims", _claims_line(e, b.status)),
                    ):
                        out += _wrap(f"{label}: {text}", width, "    ")
        out.append("")
    return "\n".join(out).rstrip() + "\n"


#: A printed formula longer than this (characters of LaTeX) is set on a line of its own under
#: its row of the unsettled claims' table, at the table's full width, not shrunk into its column.
WIDE_FORMULA = 40

_MATH_ONLY = re.compile(r"^\$[^$]+\$$")


def _raw_latex_table(t: Table, intro: str = "") -> str:
    """The book's printed table; in the unsettled claims' table a long printed formula takes a
    row of its own under its claim's row (``Printed: below``). ``intro``, the LaTeX of the
    paragraph that introduces the table, is set in the table's first head when the table takes
    the full width, so that no page break parts the two (else it precedes the table, with room
    kept for a few rows)."""
    from navcore.ledger.tables import latex_table
    from navcore.ledger.text import fit_math

    rows = [list(r) for r in t.rows]
    wide: dict[int, str] = {}
    if "Printed" in t.head and "Why" in t.head:
        j = t.head.index("Printed")
        for k, row in enumerate(rows):
            cell = row[j].strip()
            if _MATH_ONLY.match(cell) and len(cell) > WIDE_FORMULA:
                wide[k] = cell[1:-1]
                row[j] = "below"
    block = latex_table(list(t.head), rows)
    lines = block.removeprefix("```{raw} latex\n").removesuffix("\n```").split("\n")
    if wide:
        first = lines.index(r"\hline \endfoot") + 1
        span = rf"\multicolumn{{{len(t.head)}}}{{p{{\dimexpr\linewidth-2\tabcolsep\relax}}}}"
        for k in sorted(wide, reverse=True):
            printed = rf"{span}{{\hspace*{{1.5em}}Printed: {fit_math(wide[k])}}} \\"
            lines.insert(first + k + 1, printed)
    if intro:
        head = next(i for i, line in enumerate(lines) if line.endswith(r"\endfirsthead"))
        if any(line.startswith(r"\begin{longtable}{>") for line in lines):
            span = rf"\multicolumn{{{len(t.head)}}}{{@{{}}p{{\linewidth}}@{{}}}}"
            lines[head] = rf"{span}{{\normalsize {intro}}} \\[0.5\baselineskip]" + "\n" + lines[head]
        else:
            lines.insert(0, rf"\needspace{{8\baselineskip}}{intro}" + "\n\n")
    return "\n".join(lines)


def _tex_paragraph(text: str) -> str:
    """A paragraph for LaTeX: an opening ``**...**`` in bold, ``$...$`` as math."""
    from navcore.ledger.text import tex_text

    m = re.match(r"^\*\*(.+?)\*\*(.*)$", text, re.S)
    return rf"\textbf{{{tex_text(m.group(1))}}}{tex_text(m.group(2))}" if m else tex_text(text)


_PREAMBLE = r"""\documentclass[10pt]{article}
\usepackage[a4paper,margin=1in]{geometry}
\usepackage{fontspec}
\setmainfont{FreeSerif}
\setsansfont{FreeSans}
\setmonofont{FreeMono}
\usepackage{amsmath,amssymb}
\usepackage{array,longtable,graphicx,needspace}
\usepackage[hidelinks]{hyperref}
\usepackage{enumitem}
\setlist{itemsep=1pt,topsep=2pt,parsep=0pt}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.5\baselineskip}
\renewcommand{\arraystretch}{1.15}
\tolerance=2000
\emergencystretch=2em
"""


def to_latex(report: Report) -> str:
    r"""The report as a stand-alone XeLaTeX document; its title page carries the provenance.

    Tables are the book's printed tables (:func:`navcore.ledger.tables.latex_table`, which
    fit the text width); the findings are the errata page's printed list
    (:class:`navcore.ledger.tables.ErrataList`).

    Examples
    --------
    >>> r = Report("WF", "Verification report: WF", "a paper", build_provenance(),
    ...            (Section("overview", "Summary", ("50 % of $K_1$.",)),))
    >>> tex = to_latex(r)
    >>> r"50 \% of $K_1$." in tex, tex.rstrip().endswith(r"\end{document}")
    (True, True)
    """
    from navcore.ledger.tables import ErrataList
    from navcore.ledger.text import FIT_MATH_PREAMBLE, tex_breakable, tex_escape

    p = report.provenance
    date = p.date if p.date != "unknown" else "commit date unknown"
    prov = "\n".join(
        rf"{tex_escape(w)} & \texttt{{{tex_breakable(v) if len(v) > 40 else tex_escape(v)}}}\\"
        for w, v in p.rows()
    )
    out = [
        _PREAMBLE + FIT_MATH_PREAMBLE,  # the tables' long formulas (fit_math)
        rf"\hypersetup{{pdftitle={{{tex_escape(report.title)}}},pdfauthor={{navcore}}}}",
        r"\begin{document}",
        r"\begin{titlepage}\raggedright",
        r"\vspace*{3cm}{\LARGE\bfseries " + tex_escape(report.title) + r"\par}\bigskip",
        r"{\large " + tex_escape(report.reference) + r"\par}\bigskip",
        r"{\large Generated by navcore from the verification ledger\par}\medskip",
        r"{\large " + tex_escape(date) + r"\par}\vfill",
        r"{\small\itshape Built from\par}\smallskip",
        r"{\footnotesize\begin{tabular}{@{}l@{\enspace}p{0.7\linewidth}@{}}",
        prov,
        r"\end{tabular}\par}",
        r"\end{titlepage}",
    ]
    for s in report.sections:
        out.append(r"\needspace{10\baselineskip}\section*{" + tex_escape(s.title) + "}")
        for i, b in enumerate(s.blocks):
            if isinstance(b, str):
                if i + 1 < len(s.blocks) and isinstance(s.blocks[i + 1], Table):
                    continue  # the paragraph that introduces a table goes with it
                out.append(_tex_paragraph(b) + "\n")
            elif isinstance(b, Table):
                before = s.blocks[i - 1] if i else None
                out.append(_raw_latex_table(b, _tex_paragraph(before) if isinstance(before, str) else ""))
            else:
                evals_status = b.status
                lst = ErrataList(list(b.errata), caveat=False)
                lst.status = dict(evals_status)
                out.append(lst.latex())
    out.append(r"\end{document}")
    return "\n".join(out) + "\n"


_OVERFULL = re.compile(r"^Overfull \\hbox \((\d+(?:\.\d+)?)pt too wide\)(.*)$", re.M)


def write_pdf(report: Report, out: Path | str, *, max_overfull: float = 3.0) -> Path:
    """Typeset ``report`` with XeLaTeX into the PDF ``out``, strictly.

    Parameters
    ----------
    report : Report
        The report (:func:`build_report`).
    out : path
        The PDF to write; its folder is created.
    max_overfull : float, optional
        The widest overfull box allowed, pt (the book's PDF gate allows 3 pt).

    Returns
    -------
    pathlib.Path
        ``out``.

    Raises
    ------
    FileNotFoundError
        If ``xelatex`` is not on the PATH.
    RuntimeError
        If XeLaTeX fails (with the end of its log) or a box runs over by more than
        ``max_overfull``.
    """
    xelatex = shutil.which("xelatex")
    if xelatex is None:
        raise FileNotFoundError("xelatex is not on the PATH: install TeX (see the README's pdf session)")
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="navcore-report-") as tmp:
        tex = Path(tmp) / "report.tex"
        tex.write_text(to_latex(report), encoding="utf-8")
        for _ in range(3):  # a longtable may settle its column widths on a later run
            proc = subprocess.run(
                [xelatex, "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape", tex.name],
                cwd=tmp, capture_output=True, text=True, check=False, timeout=300,
            )  # fmt: skip
            log = (Path(tmp) / "report.log").read_text(encoding="utf-8", errors="replace")
            if proc.returncode != 0:
                raise RuntimeError(f"xelatex failed on the {report.paper} report:\n{log[-3000:]}")
            if "Rerun LaTeX" not in log and "Label(s) may have changed" not in log:
                break
        wide = [(float(w), where) for w, where in _OVERFULL.findall(log) if float(w) > max_overfull]
        if wide:
            listed = "; ".join(f"{w} pt{where}" for w, where in wide)
            raise RuntimeError(f"the {report.paper} report has overfull boxes: {listed}")
        shutil.copyfile(Path(tmp) / "report.pdf", out)
    return out


def write_reports(
    out_dir: Path | str, papers: Sequence[str] = tuple(PAPERS), *, pdf: bool = True
) -> list[Path]:
    """Write each paper's report as Markdown (and PDF) into ``out_dir``: ``<PAPER>.md``, ``.pdf``.

    Parameters
    ----------
    out_dir : path
        The folder (created).
    papers : sequence of str, optional
        Paper keys (default: all four).
    pdf : bool, optional
        Also typeset the PDF (:func:`write_pdf`; needs XeLaTeX).

    Returns
    -------
    list of pathlib.Path
        The files written.
    """
    from concurrent.futures import ThreadPoolExecutor

    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    provenance = build_provenance()
    reports = [build_report(check_paper(paper), provenance=provenance) for paper in papers]
    written = []
    for report in reports:
        md = out_dir / f"{report.paper}.md"
        href = Path(os.path.relpath(project_root() / "figures", out_dir.resolve())).as_posix()
        md.write_text(to_markdown(report, href), encoding="utf-8")
        written.append(md)
    if pdf:  # XeLaTeX runs as a subprocess: one per core at a time
        with ThreadPoolExecutor(max_workers=max(1, min(len(reports), os.cpu_count() or 1))) as pool:
            written += list(pool.map(lambda r: write_pdf(r, out_dir / f"{r.paper}.pdf"), reports))
    return written
