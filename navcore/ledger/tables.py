"""The ledger's tables: plain text for the terminal, HTML and LaTeX for the book, JSON and CSV.

The book shows tables through :class:`LedgerTable` (a chapter's claims, grouped by what they
check), :class:`ErrataList`, :class:`CountsTable` and :class:`FindingsTable`: each has
``_repr_html_`` for the HTML builder and ``_repr_markdown_`` returning a raw-LaTeX block for
the PDF builder (:func:`latex_table`). :func:`text_table`, :func:`json_export` and
:func:`csv_export` are the command line's outputs.
"""

from __future__ import annotations

import csv
import html
import io
import json
import re
from collections.abc import Iterable, Sequence

from navcore.claims.declarations import ERRATUM_BASES, STATUSES, TEXT_ONLY_CAVEAT, Erratum
from navcore.claims.evaluation import Evaluation
from navcore.formatting import math_spans
from navcore.ledger.registry import counts, errata, evaluations
from navcore.ledger.summary import finding_evidence, findings_count_table, summary_text
from navcore.ledger.text import (
    _ERRATUM_WIDE_MATH,
    _FIT_MATH_CHARS,
    _LONG_WORD,
    _agreeing_reading_text,
    _band_text,
    _below_words,
    _breakable_heading,
    _inputs_text,
    _printed_html,
    _printed_tex,
    _printed_text,
    _reproduced_text,
    _status_class,
    _status_colour,
    _tolerance_text,
    _value_html,
    claim_group,
    fit_math,
    format_value,
    html_text,
    published_text,
    quote_below,
    tex_breakable,
    tex_escape,
    tex_text,
)
from navcore.provenance import BuildProvenance, build_provenance

__all__ = [
    "CountsTable",
    "ErrataList",
    "FindingsTable",
    "LedgerTable",
    "csv_export",
    "group_claims",
    "json_dump",
    "json_export",
    "latex_table",
    "rows",
    "text_table",
]


def rows(evals: Iterable[Evaluation]) -> list[dict[str, str]]:
    """Table rows (strings) for a sequence of evaluations.

    Parameters
    ----------
    evals : iterable of Evaluation
        The evaluations (from :func:`~navcore.ledger.registry.evaluations`).

    Returns
    -------
    list of dict of str to str
        One row per evaluation, keys ``id``, ``locator``, ``quantity``, ``published`` (with
        its relation), ``reproduced``, ``band``, ``unit``, ``kind``, ``tolerance``,
        ``policy``, ``status`` (derived), ``check`` (``"ok"`` or ``"FAIL"``: whether
        the claim passes its own check), ``note``, ``tolerance_reason``, ``erratum`` and ``discussed_in``.

    Examples
    --------
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> row = rows([ev])[0]
    >>> row["published"], row["reproduced"], row["tolerance"], row["status"], row["check"]
    ('17.67', '17.671', '±0.005', 'reproduced', 'ok')
    """
    out = []
    for e in evals:
        c = e.claim
        tol = e.tolerance if e.tolerance is not None else c.tolerance
        band = "" if e.band is None else f"{format_value(e.band[0])} to {format_value(e.band[1])}"
        out.append(
            {
                "id": c.id,
                "locator": c.locator,
                "quantity": c.quantity,
                "published": published_text(e),
                "reproduced": format_value(e.reproduced),
                "band": band,
                "unit": c.unit,
                "kind": str(c.kind),
                "tolerance": tol.describe() if hasattr(tol, "describe") else "",
                "policy": getattr(tol, "policy", ""),
                "status": e.status,
                "check": "ok" if e.passes else "FAIL",
                "note": e.note(),
                "tolerance_reason": getattr(tol, "reason", ""),
                "erratum": c.erratum,
                "discussed_in": c.discussed_in,
            }
        )
    return out


def text_table(evals: Sequence[Evaluation], *, width: int = 38) -> str:
    """A fixed-width text table with a counts footer (for ``python -m navcore ledger``).

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations to show, in order.
    width : int, optional
        Longest cell, in characters; a longer one is cut and ends in ``…``.

    Returns
    -------
    str
        Columns id, locator, published, reproduced, unit, tolerance, status and check, then
        a blank line and :func:`~navcore.ledger.summary.summary_text`.

    Examples
    --------
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> for line in text_table([ev]).splitlines()[:3]:
    ...     print(line.rstrip())
    id            locator   published  reproduced  unit   tolerance  status      check
    ------------  --------  ---------  ----------  -----  ---------  ----------  -----
    SP-doc-omega  Fig. 2.1  17.67      17.671      rad/s  ±0.005     reproduced  ok
    """
    cols = ["id", "locator", "published", "reproduced", "unit", "tolerance", "status", "check"]
    data = rows(evals)

    def clip(s: str) -> str:
        return s if len(s) <= width else s[: width - 1] + "…"

    widths = {k: max([len(k)] + [len(clip(r[k])) for r in data]) for k in cols}
    lines = ["  ".join(k.ljust(widths[k]) for k in cols)]
    lines.append("  ".join("-" * widths[k] for k in cols))
    for r in data:
        lines.append("  ".join(clip(r[k]).ljust(widths[k]) for k in cols))
    lines.append("")

    lines.append(summary_text(evals))
    return "\n".join(lines)


def json_dump(evals: Sequence[Evaluation]) -> str:
    """The ledger as a JSON array of claim objects (the ledger's fields), stable and sorted.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations, in the order they are written.

    Returns
    -------
    str
        A JSON array (indented by two spaces, Unicode kept) of
        :meth:`~navcore.claims.evaluation.Evaluation.as_json` records.

    Examples
    --------
    >>> import json
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> record = json.loads(json_dump([ev]))[0]
    >>> record["id"], record["published"], record["reproduced"], record["status"]
    ('SP-doc-omega', 17.67, 17.671, 'reproduced')
    """
    return json.dumps([e.as_json() for e in evals], indent=2, ensure_ascii=False, sort_keys=False)


def json_export(evals: Sequence[Evaluation], provenance: BuildProvenance | None = None) -> str:
    """The ledger export: the build's provenance and the array of claim objects.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations, in the order they are written.
    provenance : BuildProvenance, optional
        What computed them (default: :func:`~navcore.provenance.build_provenance` of this
        checkout). It depends on the commit, never on the clock, so two evaluations of one
        commit export the same bytes.

    Returns
    -------
    str
        A JSON object ``{"provenance": {...}, "claims": [...]}``, indented by two spaces, whose
        ``claims`` are the records of :func:`json_dump`.

    Examples
    --------
    >>> import json
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> data = json.loads(json_export([evaluate(c)]))
    >>> sorted(data), data["claims"][0]["id"], "lock_sha256" in data["provenance"]
    (['claims', 'provenance'], 'SP-doc-omega', True)
    """
    if provenance is None:
        provenance = build_provenance()
    data = {"provenance": provenance.as_dict(), "claims": [e.as_json() for e in evals]}
    return json.dumps(data, indent=2, ensure_ascii=False, sort_keys=False)


def csv_export(evals: Sequence[Evaluation], provenance: BuildProvenance | None = None) -> str:
    """The ledger as CSV: the rows of :func:`rows`, each with the build's provenance.

    Every row carries the same ``build_*`` columns (commit, state of the tree, commit date,
    lock hash, Python and core package versions; :meth:`BuildProvenance.flat
    <navcore.provenance.BuildProvenance.flat>`), so that the file stays one plain table that
    any CSV reader takes, and a row copied elsewhere still says what computed it.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations, in the order they are written.
    provenance : BuildProvenance, optional
        What computed them (default: this checkout's).

    Returns
    -------
    str
        The CSV text, a header row first (the csv module's dialect: lines end in CR LF).

    Examples
    --------
    >>> import csv, io
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> from navcore.provenance import BuildProvenance
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> build = BuildProvenance("0" * 40, "clean", "2026-01-01T00:00:00+00:00", "f" * 64, "3.11.7", ())
    >>> row = next(csv.DictReader(io.StringIO(csv_export([evaluate(c)], build))))
    >>> row["id"], row["status"], row["build_tree"], row["build_commit_date"]
    ('SP-doc-omega', 'reproduced', 'clean', '2026-01-01T00:00:00+00:00')
    """
    if provenance is None:
        provenance = build_provenance()
    build = provenance.flat()
    data = [{**row, **build} for row in rows(evals)]
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=list(data[0]) if data else ["id", *build])
    writer.writeheader()
    writer.writerows(data)
    return buf.getvalue()


_NUMBER = re.compile(r"^[−+-]?(?:\d[\d,]*\.?\d*|\.\d+)(?:[eE][−+-]?\d+)?(?:\s*%)?$")


#: Width of the PDF's text, pt (A4, one-inch margins), and an upper estimate of a character's
#: width in the tables' footnotesize FreeSerif, pt (capitals and bold are wider).
_LINE_PT = 451.0


_CHAR_PT = {"lower": 4.0, "upper": 5.0}


_BOLD = 1.1


_PAD_PT = 8.0  # 2 \tabcolsep


def _word_pt(word: str, bold: bool = False) -> float:
    """Upper estimate of the printed width of an unbreakable ``word``, pt."""
    pt = sum(_CHAR_PT["upper"] if ch.isupper() or ch in "%&@MW" else _CHAR_PT["lower"] for ch in word)
    return pt * (_BOLD if bold else 1.0)


def _text_pieces(text: str) -> list[tuple[bool, str]]:
    """A text cell as math and text pieces, long text words cut where they may break."""
    out: list[tuple[bool, str]] = []
    for is_math, piece in math_spans(text):
        if is_math:
            out.append((True, piece))
            continue
        words = re.split(r"(\s+|\u200b)", piece)
        cut = []
        for w in words:
            if len(w) > _LONG_WORD:
                parts = re.split(r"(?<=[-./_])", w)
                w = "\u200b".join(
                    "\u200b".join(q[i : i + 7] for i in range(0, len(q), 7)) if len(q) > _LONG_WORD else q
                    for q in parts
                )
            cut.append(w)
        out.append((False, "".join(cut)))
    return out


def _min_pt(text: str, numeric: bool, bold: bool = False) -> float:
    """The widest piece of ``text`` that cannot break, pt (a math span counts whole)."""
    if numeric:
        return _word_pt(text, bold)
    widest = 0.0
    for is_math, piece in _text_pieces(text):
        if is_math:
            # a long formula is scaled down to its column (fit_math): it counts as a short one
            shown = re.sub(r"\\[a-zA-Z]+|[{}_^]", "x", piece)[:_FIT_MATH_CHARS]
            widest = max(widest, 0.8 * _word_pt(shown))
        else:
            widest = max([widest] + [_word_pt(w, bold) for w in re.split(r"\s+|\u200b", piece)])
    return widest


def latex_table(head: Sequence[str], body: Sequence[Sequence[str]]) -> str:
    r"""The book's one printed table: a ``longtable`` that fits the text width.

    Every column is at least as wide as its widest word (heading or cell) that cannot break;
    what the page has beyond that goes to the columns in proportion to how much longer their
    text is. A table whose widest words do not fit is set one size smaller. Numbers are
    right-aligned and never broken across lines; text cells wrap ragged-right without
    hyphenation, a word longer than 14 characters breaks every 7 characters or after ``-``,
    ``.``, ``/`` or ``_``, and ``$...$`` is set as math. Used for every pandas table and count
    table in the PDF.

    Parameters
    ----------
    head : sequence of str
        The column headings (set in bold); their number fixes the number of columns.
    body : sequence of sequence of str
        The rows; cells are converted with ``str`` and short rows are padded with empty
        cells. A zero-width space in a cell marks where it may break.

    Returns
    -------
    str
        A MyST ``{raw} latex`` block holding the table, ready to be emitted as Markdown.

    Examples
    --------
    >>> block = latex_table(["Paper", "Claims"], [["SP", "155"], ["KZL", "48"]])
    >>> print("\n".join(block.splitlines()[-6:-3]))
    \hline \endfoot
    SP & \mbox{155} \\
    KZL & \mbox{48} \\

    A heading's formula is set as math too:

    >>> print(latex_table(["$\\sigma_0$ (ns)"], [["5"]]).splitlines()[3])
    \hline \textbf{$\sigma_0$ (ns)} \\ \hline \endfirsthead
    """
    ncols = len(head)
    cells = [[str(c) for c in row] + [""] * (ncols - len(row)) for row in body]
    numeric = [
        all(_NUMBER.match(row[j].strip()) or not row[j].strip() for row in cells)
        and any(row[j].strip() for row in cells)
        for j in range(ncols)
    ]

    def need(j: int) -> float:
        words = [1.25 * len(w) + 1 for w in str(head[j]).split()] or [1.0]  # bold headings
        lengths = [len(row[j]) for row in cells] or [1]
        if numeric[j]:
            longest = float(max(lengths))
        else:  # long text gets more room, but less than in proportion (it wraps)
            longest = min(max(lengths), 12.0 + (sum(lengths) / len(lengths)) ** 0.75)
        return max(max(words), longest, 3) * _CHAR_PT["lower"]

    least = [
        max([_min_pt(str(head[j]), False, bold=True)] + [_min_pt(row[j], numeric[j]) for row in cells])
        for j in range(ncols)
    ]
    size, scale = r"\footnotesize", 1.0
    if sum(least) + _PAD_PT * ncols > _LINE_PT:  # the widest words do not fit: one size smaller
        size, scale = r"\scriptsize", 6.0 / 8.0
    least = [w * scale for w in least]
    wanted = [max(need(j) * scale, least[j]) for j in range(ncols)]
    room = _LINE_PT - _PAD_PT * ncols - sum(least)
    spare = sum(wanted) - sum(least)
    share = min(1.0, max(room, 0.0) / spare) if spare > 0 else 0.0
    widths = [least[j] + share * (wanted[j] - least[j]) + _PAD_PT for j in range(ncols)]
    total = sum(widths)
    natural = sum(max([1.25 * len(str(head[j]))] + [len(row[j]) for row in cells]) for j in range(ncols))
    cols = "".join(
        (r">{\raggedleft\arraybackslash}" if numeric[j] else r">{\raggedright\arraybackslash}")
        + rf"p{{\dimexpr {widths[j] / total:.4f}\linewidth-2\tabcolsep\relax}}"
        for j in range(ncols)
    )
    if natural <= 60:  # a narrow table keeps its natural width
        cols = "".join("r" if numeric[j] else "l" for j in range(ncols))

    def text_cell(text: str) -> str:  # words escaped, $...$ set as math
        return "".join(
            fit_math(piece) if is_math else tex_escape(piece).replace("\u200b", r"\allowbreak{}")
            for is_math, piece in _text_pieces(text)
        )

    def cell(text: str, j: int) -> str:
        if numeric[j]:
            text = tex_escape(text)
            return rf"\mbox{{{text}}}" if text else text
        text = text_cell(text)
        if text.startswith("["):  # after the previous row's \\ a "[" would read as its option
            text = "{}" + text
        return text

    header = " & ".join(rf"\textbf{{{text_cell(str(h))}}}" for h in head)
    out = [
        rf"\begingroup{size}\setlength{{\tabcolsep}}{{4pt}}\hyphenpenalty=10000\exhyphenpenalty=10000",
        rf"\begin{{longtable}}{{{cols}}}",
        rf"\hline {header} \\ \hline \endfirsthead",
        rf"\hline {header} \\ \hline \endhead",
        r"\hline \endfoot",
    ]
    out += [" & ".join(cell(c, j) for j, c in enumerate(row)) + r" \\" for row in cells]
    out += [r"\end{longtable}", r"\endgroup"]
    return "```{raw} latex\n" + "\n".join(out) + "\n```"


_DETAIL_FIELDS = ("note", "tolerance", "band", "inputs")


_DETAIL_LABELS = {
    "note": "",
    "tolerance": "Tolerance",
    "band": "Over the assumed inputs' ranges",
    "inputs": "Inputs",
}


class _Group:
    """Consecutive claims that check the same table, figure, equation or section."""

    def __init__(self, label: str, evals: list[Evaluation]) -> None:
        self.label = label
        self.evals = evals
        self.details = [
            {
                "note": e.note(),
                "tolerance": _tolerance_text(e),
                "band": _band_text(e),
                "inputs": _inputs_text(e),
            }
            for e in evals
        ]
        locators = {e.claim.locator for e in evals}
        # the header shows the full locator when every claim shares it
        self.heading = locators.pop() if len(locators) == 1 else label
        # a detail shared by every claim of a group of two or more is said once, in the header
        self.shared = {
            k: self.details[0][k]
            for k in _DETAIL_FIELDS
            if len(evals) > 1 and self.details[0][k] and all(d[k] == self.details[0][k] for d in self.details)
        }
        # notes that open with the same sentences (a scenario described once per claim): the
        # common opening is said once in the header, each claim keeps the rest of its note
        # (or several of them do: the largest set of two or more whose notes start alike; their
        # notes then continue with "…")
        self._partial: set[str] = set()
        self.shared_by = len(evals) if self.shared else 0
        if len(evals) > 1 and "note" not in self.shared:
            starts: dict[str, list[int]] = {}
            for i, d in enumerate(self.details):
                if d["note"]:
                    starts.setdefault(d["note"][:_MIN_SHARED_OPENING], []).append(i)
            members = max(starts.values(), key=len, default=[])
            opening = _common_opening([self.details[i]["note"] for i in members]) if len(members) > 1 else ""
            if opening:
                self.shared["note"] = opening
                self._partial.add("note")
                self.shared_by = len(members)
                for i in members:
                    rest = self.details[i]["note"][len(opening) :].strip()
                    self.details[i]["note"] = rest if len(members) == len(evals) else "… " + rest

    def own(self, index: int) -> dict[str, str]:
        """The details of claim ``index`` that the group does not share."""
        return {
            k: v for k, v in self.details[index].items() if v and (k not in self.shared or k in self._partial)
        }


def _shared_label(shared_by: int, n: int) -> str:
    """Summary of a group's shared note: all of its claims, or some."""
    if shared_by == n:
        return f"note for these {n} claims"
    return f"note shared by {shared_by} of these {n} claims"


#: Words whose full stop does not end a sentence.
_ABBREVIATIONS = {"e.g", "i.e", "eq", "eqs", "fig", "figs", "sec", "secs", "cf", "vs", "no", "ref", "approx"}


#: A common opening of the notes of a group is said once only if it is at least this long.
_MIN_SHARED_OPENING = 120


def _common_opening(notes: list[str]) -> str:
    """The longest run of whole sentences that every note opens with ("" if short or none).

    A sentence ends at ". " outside inline math; the opening must leave every note some text of
    its own (notes that are all equal are shared whole instead).
    """
    if not notes or any(not n for n in notes):
        return ""
    first = notes[0]
    length = len(first)
    for n in notes[1:]:
        i = 0
        while i < min(length, len(n)) and first[i] == n[i]:
            i += 1
        length = i
    cut = 0
    in_math = False
    for i, ch in enumerate(first[:length]):
        if ch == "$" and (i == 0 or first[i - 1] != "\\"):
            in_math = not in_math
        elif ch == "." and not in_math and i + 1 < length and first[i + 1] == " ":
            word = first[:i].rsplit(" ", 1)[-1].lstrip("(").lower()
            if word not in _ABBREVIATIONS:
                cut = i + 1
    opening = first[:cut]
    if len(opening) < _MIN_SHARED_OPENING or any(len(n.strip()) <= cut for n in notes):
        return ""
    return opening.strip()


def _locator_detail(locator: str, heading: str) -> str:
    """What a claim's locator adds to its group's heading (``"column 2"`` under
    ``"Table 2.6"``); empty when it adds nothing."""
    if locator == heading:
        return ""
    if locator.startswith(heading):
        rest = locator[len(heading) :].lstrip(" ,;")
        return rest if rest and not rest.startswith(")") else locator
    return locator


def group_claims(evals: Sequence[Evaluation]) -> list[_Group]:
    """``evals`` cut into runs of consecutive claims that check the same thing.

    A run of two or more consecutive claims with one locator (``"Table 2.6, column 2"``)
    is a group of its own, headed by that locator; other claims are grouped by
    :func:`~navcore.ledger.text.claim_group` of their locators (``"Table 2.6"``).

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations, in the order they are shown.

    Returns
    -------
    list of group
        The groups in order; each has ``label`` (the grouping key), ``heading`` (the full
        locator when all its claims share it, else the label), ``evals`` (its evaluations),
        ``details`` (per claim: note, tolerance, band and inputs as text) and ``shared``
        (the details every claim of a group of two or more shares).

    Examples
    --------
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> [(g.heading, len(g.evals)) for g in group_claims([ev, ev])]
    [('Fig. 2.1', 2)]
    """
    locators = [e.claim.locator for e in evals]
    keys = []
    for i, loc in enumerate(locators):
        same_run = (i > 0 and locators[i - 1] == loc) or (i + 1 < len(locators) and locators[i + 1] == loc)
        keys.append(loc if same_run else claim_group(loc))
    groups: list[_Group] = []
    start = 0
    for i in range(1, len(evals) + 1):
        if i == len(evals) or keys[i] != keys[start]:
            groups.append(_Group(keys[start], list(evals[start:i])))
            start = i
    return groups


def _details_html(details: dict[str, str]) -> str:
    parts = []
    for k in _DETAIL_FIELDS:
        if details.get(k):
            label = _DETAIL_LABELS[k]
            text = html_text(details[k], wide=24)
            parts.append(f"<p><i>{label}:</i> {text}</p>" if label else f"<p>{text}</p>")
    return "".join(parts)


def _details_tex(details: dict[str, str]) -> str:
    """The details in one run of text; the printed table leaves out the inputs (the
    Assumptions page and the ledger's JSON list them) to stay compact."""
    parts = []
    for k in _DETAIL_FIELDS[:-1]:
        if details.get(k):
            label = _DETAIL_LABELS[k]
            text = tex_text(details[k])
            if not text.rstrip().endswith((".", "!", "?", ")", ":")):  # the parts run on in one line
                text = text.rstrip() + "."
            parts.append(rf"\textit{{{label}:}} {text}" if label else text)
    return " ".join(parts)


_KIND_LABELS = {
    "reproduction": "reproduction",
    "cross-check": "cross-check",
    "statement": "statement",
    "fit": "fit",
}


class LedgerTable:
    """Printed-versus-reproduced table of a chapter's claims (HTML and PDF).

    Claims are grouped by what they check (:func:`~navcore.ledger.text.claim_group` of their locators):
    consecutive claims of one table, figure, equation or section share a header row naming
    it. Each claim is one line: what it checks, the printed and the reproduced value with
    their unit (a statement reads "stated" / "holds"), its verdict as a coloured badge and
    its kind; a quoted equation too wide for the Printed column (``quote_below``) follows
    on a line of its own, the table's width. The note, the tolerance with its reason, the
    band and the inputs sit behind a disclosure; what every claim of a group shares is said
    once, in the group's header.
    Each row carries the lower-cased claim id as its anchor.

    Parameters
    ----------
    evals : sequence of Evaluation
        The claims to show, in order.
    show_notes : bool
        Include the notes, tolerances and inputs (HTML: disclosures; PDF: small type).
    link_errata : bool
        Link erratum ids to their entry on the errata page.
    root : str
        Relative path from the page showing the table to the book's root (``"../"`` for a
        chapter page, ``""`` for a top-level page).
    link_pages : bool
        Link each claim id to its row on the page that discusses it (for the ledger page).

    Examples
    --------
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> html = LedgerTable([ev])._repr_html_()
    >>> 'id="sp-doc-omega"' in html, "17.671&nbsp;rad/s" in html
    (True, True)
    """

    def __init__(
        self,
        evals: Sequence[Evaluation],
        *,
        show_notes: bool = True,
        link_errata: bool = True,
        root: str = "../",
        link_pages: bool = False,
    ) -> None:
        self.evals = list(evals)
        self.root = root
        self.show_notes = show_notes
        self.link_errata = link_errata
        self.link_pages = link_pages

    def groups(self) -> list[_Group]:
        """The claims cut into groups (see :func:`group_claims`)."""
        return group_claims(self.evals)

    # -- HTML ------------------------------------------------------------------------------

    def _verdict_html(self, e: Evaluation) -> str:
        status = html.escape(e.status)
        out = f'<span class="ledger-badge {_status_class(e.status)}">{status}</span>'
        if not e.passes:
            out += ' <b class="ledger-fails">check fails</b>'
        if e.claim.erratum and self.link_errata:
            anchor = html.escape(e.claim.erratum.lower())
            out += (
                f' <a class="ledger-erratum" href="{html.escape(self.root)}errata.html#{anchor}">'
                f"{html.escape(e.claim.erratum)}</a>"
            )
        reading = _agreeing_reading_text(e)
        if reading:
            out += f' <span class="ledger-reading">{html_text(reading)}</span>'  # a label may hold math
        return out

    def _claim_id_html(self, e: Evaluation) -> str:
        c = e.claim
        code = f"<code>{html.escape(c.id)}</code>"
        if self.link_pages and c.discussed_in:
            target = html.escape(f"{self.root}{c.discussed_in}.html#{c.id.lower()}")
            code = f'<a href="{target}" title="where the book derives it">{code}</a>'
        return code

    def _repr_html_(self) -> str:
        head = ("What it checks", "Printed", "Reproduced", "Verdict", "Kind")
        out = [
            '<div class="ledger-claims-wrap"><table class="ledger-claims">',
            "<thead><tr>" + "".join(f'<th scope="col">{h}</th>' for h in head) + "</tr></thead>",
        ]
        for g in self.groups():
            out.append("<tbody>")
            shared = _details_html(g.shared) if self.show_notes else ""
            n = len(g.evals)
            header = f'<span class="ledger-group-label">{html_text(g.heading)}</span>'
            if shared:
                header += (
                    f'<details class="ledger-shared"><summary>{_shared_label(g.shared_by, n)}</summary>'
                    f"{shared}</details>"
                )
            out.append(f'<tr class="ledger-group"><th colspan="5" scope="rowgroup">{header}</th></tr>')
            for index, e in enumerate(g.evals):
                c = e.claim
                what = html_text(c.quantity, wide=24)
                where = _locator_detail(c.locator, g.heading)
                if where:
                    what += f' <span class="ledger-locator">({html.escape(where)})</span>'
                if self.show_notes:
                    own = _details_html(g.own(index))
                    what += (
                        '<details class="ledger-details"><summary>details</summary>'
                        f'<p class="ledger-id">Claim {self._claim_id_html(e)}</p>{own}</details>'
                    )
                elif self.link_pages:
                    what += f' <span class="ledger-id">{self._claim_id_html(e)}</span>'
                kind = html.escape(_KIND_LABELS.get(str(c.kind), str(c.kind)))
                printed = _printed_text(e)
                below = quote_below(printed)
                cells = (
                    ("ledger-what", "", what),
                    (
                        "ledger-value",
                        "Printed",
                        f'<span class="ledger-quote-below">{_below_words(printed)}</span>'
                        if below
                        else _printed_html(printed),
                    ),
                    ("ledger-value", "Reproduced", _value_html(_reproduced_text(e))),
                    ("ledger-verdict", "Verdict", self._verdict_html(e)),
                    ("ledger-kind", "Kind", f'<span class="ledger-kind-label">{kind}</span>'),
                )
                tds = "".join(
                    f'<td class="{cls}"' + (f' data-label="{label}"' if label else "") + f">{body}</td>"
                    for cls, label, body in cells
                )
                status = html.escape(e.status)
                out.append(
                    f'<tr id="{html.escape(c.id.lower())}" class="ledger-claim'
                    f'{" ledger-claim-quoted" if below else ""}" data-status="{status}">{tds}</tr>'
                )
                if below:  # the quote on a line of its own, the width of the table
                    out.append(
                        f'<tr id="{html.escape(c.id.lower())}-quote" class="ledger-claim-quote" '
                        f'data-status="{status}">'
                        f'<td colspan="5" data-label="Printed">{_printed_html(printed)}</td></tr>'
                    )
            out.append("</tbody>")
        out.append("</table></div>")
        return "".join(out)

    # -- PDF -------------------------------------------------------------------------------

    def _repr_markdown_(self) -> str:
        """A raw-LaTeX block for the PDF book (MyST renders Markdown outputs there); the HTML
        builder uses :meth:`_repr_html_`."""
        return "```{raw} latex\n" + self.latex() + "\n```"

    def latex(self) -> str:
        """The table as a compact LaTeX ``longtable`` that fits the text width.

        Four columns (what it checks, printed, reproduced, verdict with the kind below it);
        a group's header row spans the width and holds, in small type, the note shared by
        its claims; a claim's own note follows its quantity in small type; a quoted equation
        too wide for the Printed column (``quote_below``) follows its claim's row on a
        line of its own, centred across the table and kept on the row's page.
        """
        widths = (0.49, 0.16, 0.16, 0.19)
        align = (r"\raggedright", r"\raggedright", r"\raggedleft", r"\raggedright")
        cols = "".join(
            rf">{{{a}\arraybackslash}}p{{\dimexpr {w}\linewidth-2\tabcolsep\relax}}"
            for a, w in zip(align, widths, strict=True)
        )
        head = " & ".join(rf"\textbf{{{h}}}" for h in ("What it checks", "Printed", "Reproduced", "Verdict"))
        full = r"\multicolumn{4}{>{\raggedright\arraybackslash}p{\dimexpr\linewidth-2\tabcolsep\relax}}"
        centred = r"\multicolumn{4}{>{\centering\arraybackslash}p{\dimexpr\linewidth-2\tabcolsep\relax}}"
        out = [
            r"\begingroup\footnotesize\setlength{\tabcolsep}{3pt}\sloppy",
            rf"\begin{{longtable}}{{{cols}}}",
            rf"\hline {head} \\ \hline \endfirsthead",
            rf"\hline {head} \\ \hline \endhead",
            r"\hline \endfoot",
        ]
        for g in self.groups():
            header = r"\textbf{" + tex_text(g.heading) + "}"
            if self.show_notes and g.shared:
                some = "" if g.shared_by == len(g.evals) else _shared_label(g.shared_by, len(g.evals)) + ": "
                header += r"\newline{}{\scriptsize " + some + _details_tex(g.shared) + "}"
            out.append(rf"\rowcolor[HTML]{{F1F3F5}}{full}{{{header}}} \\*")
            for index, e in enumerate(g.evals):
                c = e.claim
                what = tex_text(c.quantity)
                where = _locator_detail(c.locator, g.heading)
                if where:
                    what += " (" + tex_escape(where) + ")"
                if self.show_notes:
                    own = _details_tex(g.own(index))
                    what += r"\newline{}{\scriptsize \texttt{" + tex_breakable(c.id) + "}"
                    what += (". " + own if own else "") + "}"
                colour = _status_colour(e.status).lstrip("#").upper()
                verdict = rf"\cellcolor[HTML]{{{colour}}}" + tex_breakable(e.status)
                if not e.passes:
                    verdict += r" \textbf{(check fails)}"
                if c.erratum:
                    verdict += r"\newline{}{\scriptsize " + tex_breakable(c.erratum) + "}"
                if _agreeing_reading_text(e):
                    verdict += r"\newline{}{\scriptsize " + tex_text(_agreeing_reading_text(e)) + "}"
                verdict += r"\newline{}{\scriptsize\itshape " + tex_escape(str(c.kind)) + "}"
                printed = _printed_text(e)
                below = quote_below(printed)
                cells = [
                    what,
                    r"\textit{" + _below_words(printed) + "}" if below else _printed_tex(printed),
                    tex_text(_reproduced_text(e)),
                    verdict,
                ]
                last = index == len(g.evals) - 1
                rule = r"\hline" if last else r"\arrayrulecolor{black!25}\hline\arrayrulecolor{black}"
                if below:  # the quote on a line of its own, the width of the table, kept with its row
                    out.append(" & ".join(cells) + r" \\*")
                    out.append(rf"{centred}{{{_printed_tex(printed)}}} \\ " + rule)
                else:
                    out.append(" & ".join(cells) + r" \\ " + rule)
        out += [r"\end{longtable}", r"\endgroup"]
        return "\n".join(out)

    def __repr__(self) -> str:
        return text_table(self.evals)


class CountsTable:
    """Counts of claims per paper and status (HTML and Markdown).

    Parameters
    ----------
    paper : str or None, optional
        Paper key; ``None`` for every paper, with a row of totals. Every claim counted is
        evaluated (:func:`~navcore.ledger.registry.counts`).

    Attributes
    ----------
    counts : dict
        :func:`~navcore.ledger.registry.counts` of ``paper``.
    failing : dict of str to int
        Per paper, the number of claims failing their check.
    """

    def __init__(self, paper: str | None = None) -> None:
        self.counts = counts(paper)
        self.failing = {p: sum(not e.passes for e in evaluations(p)) for p in self.counts}

    def _table(self) -> tuple[list[str], list[list[str]]]:
        head = ["Paper", *STATUSES, "total", "failing check"]
        body = [
            [p, *(str(row[s]) for s in STATUSES), str(row["total"]), str(self.failing[p])]
            for p, row in self.counts.items()
        ]
        if len(body) > 1:
            tot = [sum(int(r[i]) for r in body) for i in range(1, len(head))]
            body.append(["all", *map(str, tot)])
        return head, body

    def _repr_html_(self) -> str:
        head, body = self._table()
        out = ['<div class="ledger-counts-wrap"><table class="ledger-counts"><thead><tr>']
        out += [f"<th>{_breakable_heading(h)}</th>" for h in head]
        out.append("</tr></thead><tbody>")
        for r in body:
            out.append("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>")
        out.append("</tbody></table></div>")
        return "".join(out)

    def _repr_markdown_(self) -> str:
        head, body = self._table()
        return latex_table(head, body)

    def __repr__(self) -> str:
        head, body = self._table()
        return "\n".join("  ".join(row) for row in [head, *body])


_BASIS_HEADINGS = {"computed": "Computed findings", "text-only": "Text-only findings"}


def _claim_link_html(root: str, cid: str, status: str | None) -> str:
    """A claim id linked to its row on the ledger page, with its verdict as a badge if known."""
    href = html.escape(f"{root}ledger.html#{cid.lower()}")
    out = f'<a href="{href}"><code>{html.escape(cid)}</code></a>'
    if status:
        out += f' <span class="ledger-badge {_status_class(status)}">{html.escape(status)}</span>'
    return out


class ErrataList:
    """The errata as a list of entries (HTML with anchors; Markdown for the PDF).

    The entries are grouped by basis, computed findings first; each says its basis and
    kind, what the paper prints, what the book finds, the evidence, and the claims that are
    its evidence (with their verdicts when ``evals`` is given). The text-only caveat
    (:data:`~navcore.claims.declarations.TEXT_ONLY_CAVEAT`) is said once, under the heading of the
    text-only findings, never per entry.

    Parameters
    ----------
    items : sequence of Erratum or None, optional
        The errata to list; ``None`` for every registered erratum.
    root : str, optional
        Link prefix from the showing page to the book's root.
    titles : dict of str to str or None, optional
        Page docname to its title, for the text of the links to the discussing pages.
    evals : sequence of Evaluation or None, optional
        Evaluations of the claims, to show each claim's derived verdict.
    caveat : bool, optional
        Say the text-only caveat under the text-only heading (``False`` where the page has
        said it already, as the errata page does above its lists).

    Examples
    --------
    >>> from navcore.ledger import Erratum
    >>> e = Erratum(id="SP-E9-doc", paper="SP", locator="Eq. (2.4.2)", printed="$a + b$",
    ...             finding="$a - b$", evidence="the derivation in the book", kind="typography",
    ...             basis="text-only",
    ...             no_claim_reason="a sign with no printed number to check")
    >>> ErrataList([e])
    SP-E9-doc: SP, Eq. (2.4.2) (text-only, typography)
    >>> "Text-only findings" in ErrataList([e])._repr_html_()
    True
    """

    def __init__(
        self,
        items: Sequence[Erratum] | None = None,
        *,
        root: str = "",
        titles: dict[str, str] | None = None,
        evals: Sequence[Evaluation] | None = None,
        caveat: bool = True,
    ) -> None:
        items = list(errata() if items is None else items)
        self.caveat = caveat
        order = {b: i for i, b in enumerate(ERRATUM_BASES)}
        self.items = sorted(items, key=lambda e: order.get(e.basis, len(order)))  # stable within a basis
        self.root = root
        # page -> its title, for link texts (a reader should not see file paths)
        self.titles = titles or {}
        self.status = {ev.claim.id: ev.status for ev in evals or ()}

    def _groups(self) -> list[tuple[str, list[Erratum]]]:
        return [
            (b, [e for e in self.items if e.basis == b])
            for b in ERRATUM_BASES
            if any(e.basis == b for e in self.items)
        ]

    def _claim_html(self, cid: str) -> str:
        return _claim_link_html(self.root, cid, self.status.get(cid))

    def _repr_html_(self) -> str:
        out = []
        for basis, items in self._groups():
            out.append(f'<p class="errata-group"><b>{_BASIS_HEADINGS[basis]}</b> ({len(items)})</p>')
            if basis == "text-only" and self.caveat:
                out.append(f'<p class="ledger-caveat">{html.escape(TEXT_ONLY_CAVEAT)}</p>')
            for e in items:
                link = html.escape(f"{self.root}{e.discussed_in}.html#{e.id.lower()}")
                title = html.escape(self.titles.get(e.discussed_in, "the chapter"))
                where = f' Discussed in <a href="{link}">{title}</a>.' if e.discussed_in else ""
                claims_html = ", ".join(self._claim_html(c) for c in e.claims) or "none"
                out.append(
                    f'<div class="erratum erratum-{html.escape(e.basis)}" id="{html.escape(e.id.lower())}">'
                    f"<h4>{html.escape(e.id)} — {html.escape(e.paper)}, {html_text(e.locator)}</h4>"
                    f'<p class="erratum-basis"><b>Basis:</b> {html.escape(e.basis)} · '
                    f"<b>Kind:</b> {html.escape(e.kind)}</p>"
                    f"<p><b>Printed:</b> {html_text(e.printed, wide=_ERRATUM_WIDE_MATH)}</p>"
                    f"<p><b>The book finds:</b> {html_text(e.finding, wide=_ERRATUM_WIDE_MATH)}</p>"
                    f"<p><b>Evidence:</b> {html_text(e.evidence, wide=_ERRATUM_WIDE_MATH)}</p>"
                    f"<p><b>Claims (its evidence in the ledger):</b> {claims_html}.{where}</p></div>"
                )
        return "".join(out) or "<p>No errata registered.</p>"

    def _repr_markdown_(self) -> str:
        """The printed list: a raw-LaTeX block whose ``$...$`` is math, set ``\\sloppy`` so
        that a line of formulas never runs into the margin (the HTML builder uses
        :meth:`_repr_html_`)."""
        if not self.items:
            return "No errata registered."
        return "```{raw} latex\n" + self.latex() + "\n```"

    def latex(self) -> str:
        """Each erratum as a bold heading line and an itemised list of its fields, by basis."""
        out = [r"\begingroup\sloppy"]
        for basis, items in self._groups():
            out.append(
                r"\par\medskip\noindent\textit{" + _BASIS_HEADINGS[basis] + f" ({len(items)})" + "}\\par"
            )
            if basis == "text-only" and self.caveat:
                out.append(r"\noindent{}" + tex_escape(TEXT_ONLY_CAVEAT) + r"\par")
            for e in items:
                claims_tex = (
                    "; ".join(
                        r"\texttt{"
                        + tex_breakable(c)
                        + "}"
                        + (f" ({tex_escape(self.status[c])})" if c in self.status else "")
                        for c in e.claims
                    )
                    or "none"
                )
                out += [
                    r"\par\medskip\noindent\textbf{"
                    + tex_breakable(e.id)
                    + "} ("
                    + tex_escape(e.paper)
                    + ", "
                    + tex_text(e.locator)
                    + r")\nopagebreak",
                    r"\begin{itemize}",
                    r"\item \textit{Basis:} "
                    + tex_escape(e.basis)
                    + r"; \textit{kind:} "
                    + tex_escape(e.kind),
                    r"\item \textit{Printed:} " + tex_text(e.printed),
                    r"\item \textit{The book finds:} " + tex_text(e.finding),
                    r"\item \textit{Evidence:} " + tex_text(e.evidence),
                    r"\item \textit{Claims (its evidence in the ledger):} " + claims_tex,
                    r"\end{itemize}",
                ]
        out.append(r"\endgroup")
        return "\n".join(out)

    def __repr__(self) -> str:
        return (
            "\n".join(f"{e.id}: {e.paper}, {e.locator} ({e.basis}, {e.kind})" for e in self.items)
            or "No errata registered."
        )


class FindingsTable:
    """The findings (errata) counted by paper, basis and kind, and optionally listed with
    the claims that are their evidence (HTML and PDF).

    The text-only caveat (:data:`~navcore.claims.declarations.TEXT_ONLY_CAVEAT`) follows the counts
    once, when a text-only finding is counted.

    Parameters
    ----------
    items : sequence of Erratum
        The findings.
    evals : sequence of Evaluation, optional
        The evaluations whose claims are shown as evidence (with their verdicts).
    root : str, optional
        Link prefix from the showing page to the book's root.
    list_findings : bool, optional
        Also list every finding (id linked to its entry on the errata page, basis, kind and
        its evidence).

    Examples
    --------
    >>> from navcore.ledger import Erratum
    >>> e = Erratum(id="SP-E9-doc", paper="SP", locator="Eq. (2.4.2)", printed="$a + b$",
    ...             finding="$a - b$", evidence="the derivation in the book", kind="typography",
    ...             basis="text-only", no_claim_reason="a sign with no printed number to check")
    >>> print(repr(FindingsTable([e])).splitlines()[1])
    SP  text-only  1  0  0  0  0  0  0  1
    >>> "transcription" in FindingsTable([e])._repr_html_()
    True
    """

    def __init__(
        self,
        items: Sequence[Erratum],
        evals: Sequence[Evaluation] = (),
        *,
        root: str = "",
        list_findings: bool = False,
    ) -> None:

        self.items = list(items)
        self.root = root
        self.list_findings = list_findings
        self.rows = findings_count_table(self.items)
        self.evidence = finding_evidence(self.items, list(evals))

    def _table(self) -> tuple[list[str], list[list[str]]]:
        from navcore.claims.declarations import ERRATUM_KINDS

        head = ["Paper", "Basis", *(k.replace("-", " ") for k in ERRATUM_KINDS), "Findings"]
        body = [
            [r["paper"], r["basis"], *(str(r[k]) for k in ERRATUM_KINDS), str(r["total"])] for r in self.rows
        ]
        return head, body

    def _caveat(self) -> str:
        return TEXT_ONLY_CAVEAT if any(e.basis == "text-only" for e in self.items) else ""

    def _repr_html_(self) -> str:
        head, body = self._table()
        out = ['<div class="ledger-counts-wrap"><table class="ledger-counts ledger-findings"><thead><tr>']
        out += [f"<th>{_breakable_heading(h)}</th>" for h in head]
        out.append("</tr></thead><tbody>")
        for r in body:
            out.append("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>")
        out.append("</tbody></table></div>")
        if self._caveat():
            out.append(f'<p class="ledger-caveat">{html.escape(self._caveat())}</p>')
        if self.list_findings:
            out.append(
                '<div class="ledger-table-wrap"><table class="ledger-findings-list"><thead><tr>'
                '<th scope="col">Finding</th><th scope="col">Basis</th><th scope="col">Kind</th>'
                '<th scope="col">Its evidence: claims and verdicts</th></tr></thead><tbody>'
            )
            for e, evs in self.evidence:
                anchor = html.escape(f"{self.root}errata.html#{e.id.lower()}")
                claims = (
                    ", ".join(_claim_link_html(self.root, ev.claim.id, ev.status) for ev in evs)
                    or "no claim checks it"
                )
                out.append(
                    f'<tr><td><a href="{anchor}"><code>{html.escape(e.id)}</code></a><br>'
                    f'<span class="ledger-locator">{html.escape(e.paper)}, {html_text(e.locator)}</span></td>'
                    f"<td>{html.escape(e.basis)}</td><td>{html.escape(e.kind)}</td><td>{claims}</td></tr>"
                )
            out.append("</tbody></table></div>")
        return "".join(out)

    def _repr_markdown_(self) -> str:
        head, body = self._table()
        out = latex_table(head, body)
        if self._caveat():
            out += "\n\n" + self._caveat()
        if self.list_findings:
            rows = [
                [
                    e.id.replace("-", "-\u200b"),
                    e.basis,
                    e.kind,
                    ", ".join(f"{ev.claim.id} ({ev.status})" for ev in evs).replace("-", "-\u200b")
                    or "no claim checks it",
                ]
                for e, evs in self.evidence
            ]
            out += "\n\n" + latex_table(
                ["Finding", "Basis", "Kind", "Its evidence: claims and verdicts"], rows
            )
        return out

    def __repr__(self) -> str:
        head, body = self._table()
        return "\n".join("  ".join(row) for row in [head, *body])
