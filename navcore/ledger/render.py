"""Rendering the ledger: plain text for the terminal, HTML and Markdown for the book.

The book shows tables through :class:`LedgerTable` (a chapter's claims, grouped by what they
check), :class:`InteractiveLedger` (the whole ledger) and :class:`ErrataList`: each has
``_repr_html_`` for the HTML builder and ``_repr_markdown_`` returning a raw-LaTeX block for
the PDF builder. Notes, quantities and erratum texts may hold inline math as ``$...$``
(:func:`html_text`, :func:`tex_text`); the plain-text output leaves it as written.
"""

from __future__ import annotations

import csv
import html
import io
import json
import math
import re
from collections.abc import Iterable, Sequence
from typing import Any

from navcore.formatting import format_number
from navcore.ledger.core import (
    COUNT_UNITS,
    ERRATUM_BASES,
    PRECISION_STRICT,
    STATUSES,
    TEXT_ONLY_CAVEAT,
    Erratum,
    Evaluation,
    _n_runs,
    claim_quote,
    left_out_of_band,
    reader_label,
)
from navcore.ledger.core import _is_truth as _core_is_truth
from navcore.ledger.inputs import _label_and_unit, get_input
from navcore.ledger.registry import counts, errata, evaluations
from navcore.provenance import BuildProvenance, build_provenance

__all__ = [
    "STATUS_COLOURS",
    "CountsTable",
    "ErrataList",
    "FindingsTable",
    "InteractiveLedger",
    "LedgerTable",
    "claim_group",
    "csv_export",
    "format_value",
    "group_claims",
    "html_text",
    "json_dump",
    "json_export",
    "latex_table",
    "math_spans",
    "plain_math",
    "quote_math",
    "quote_text",
    "rows",
    "tex_text",
    "text_table",
    "unit_text",
]

# light-mode row colours (the PDF uses them too); the HTML sets them by class
# (``ledger-status-<verdict>``) so that the book's dark mode can override them
STATUS_COLOURS = {
    "reproduced": "#d8f0d8",
    "consistent": "#e6f0fa",
    "discrepant": "#fbe3d4",
    "inconsistent": "#f6d6e8",
    "not-reproducible": "#eeeeee",
    "error": "#ffb3b3",
}


def _status_colour(status: str) -> str:
    return STATUS_COLOURS.get(status, "#ffffff")


def _status_class(status: str) -> str:
    return "ledger-status-" + "".join(ch if ch.isalnum() or ch == "-" else "-" for ch in status)


def format_value(value: Any, digits: int = 5) -> str:
    """Format a published or reproduced value for a table.

    Parameters
    ----------
    value : float, bool or None
        The value (a number in the claim's unit, a truth value, or ``None`` when nothing was
        computed).
    digits : int, optional
        Significant digits of a non-integral number.

    Returns
    -------
    str
        ``"—"`` for ``None``; ``"true"``/``"false"`` for a truth value; ``"∞"``/``"−∞"``;
        an integral value below a million without decimals; otherwise ``digits``
        significant digits (trailing zeros dropped), fixed between 0.001 and a million and
        otherwise in the book's one number format (``navcore.formatting.format_number``:
        ``9.4007×10⁻⁴``, never ``9.4007e-04`` or ``0.00094007``).

    Examples
    --------
    >>> format_value(17.6712345), format_value(3.0), format_value(True), format_value(None)
    ('17.671', '3', 'true', '—')
    >>> format_value(0.00094007), format_value(3.98601e14), format_value(123456.7), format_value(-1e-9)
    ('9.4007×10⁻⁴', '3.986×10¹⁴', '123457', '-1×10⁻⁹')
    """
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "true" if value else "false"
    v = float(value)
    if math.isinf(v):
        return "∞" if v > 0 else "−∞"
    if v == int(v) and abs(v) < 1e6:
        return str(int(v))
    if 1e-3 <= abs(v) < 1e6:
        text = f"{v:.{digits}g}"
        return text if "e" not in text else format_number(v, digits=digits)
    mantissa, _, exponent = format_number(v, digits=digits).partition("×")
    if "." in mantissa:  # as the fixed form: significant digits without trailing zeros
        mantissa = mantissa.rstrip("0").rstrip(".")
    return mantissa + ("×" + exponent if exponent else "")


def _published(e: Evaluation) -> str:
    c = e.claim
    rel = "" if c.relation == "=" else c.relation.replace(">=", "≥").replace("<=", "≤") + " "
    return rel + format_value(c.published)


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
                "published": _published(e),
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
    from navcore.ledger.summary import summary_text

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
        :meth:`~navcore.ledger.core.Evaluation.as_json` records.

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


def _md_escape(s: str) -> str:
    return s.replace("|", "\\|").replace("\n", " ")


_TEX_SPECIAL = {
    "\\": r"\textbackslash{}",
    "&": r"\&",
    "%": r"\%",
    "$": r"\$",
    "#": r"\#",
    "_": r"\_",
    "{": r"\{",
    "}": r"\}",
    "~": r"\textasciitilde{}",
    "^": r"\textasciicircum{}",
}


def _tex_escape(text: str) -> str:
    """Escape LaTeX's special characters (the PDF engine is XeLaTeX: Unicode passes)."""
    return "".join(_TEX_SPECIAL.get(ch, ch) for ch in text.replace("\n", " "))


def _tex_breakable(text: str) -> str:
    """Escaped text that may break after ``-``, ``.``, ``_`` and ``/``, inside a run of more than
    ten characters that is not a plain word (claim and erratum ids, locators with formulas), and
    inside a plain word only when it is longer than ``_LONG_WORD`` letters: a narrow table column
    never runs over, and the paper's words ("interpreted") stay whole.

    Examples
    --------
    >>> "allowbreak" in _tex_breakable("interpreted")
    False
    >>> _tex_breakable("KZLsec36headingX").count("allowbreak")
    2
    """
    pieces = re.split(r"([-./_ ])", text)
    out = []
    for piece in pieces:
        if len(piece) > (_LONG_WORD if piece.isalpha() else 10):
            piece = "\x00".join(piece[i : i + 7] for i in range(0, len(piece), 7))
        out.append(piece)
    escaped = _tex_escape("".join(out)).replace("\x00", r"\allowbreak{}")
    for ch in ("-", ".", "/"):
        escaped = escaped.replace(ch, ch + r"\allowbreak{}")
    return escaped.replace(r"\_", r"\_\allowbreak{}")


_NUMBER = re.compile(r"^[−+-]?(?:\d[\d,]*\.?\d*|\.\d+)(?:[eE][−+-]?\d+)?(?:\s*%)?$")


#: Width of the PDF's text, pt (A4, one-inch margins), and an upper estimate of a character's
#: width in the tables' footnotesize FreeSerif, pt (capitals and bold are wider).
_LINE_PT = 451.0
_CHAR_PT = {"lower": 4.0, "upper": 5.0}
_BOLD = 1.1
_PAD_PT = 8.0  # 2 \tabcolsep
_LONG_WORD = 14  # a longer word of a text cell may break (every 7 characters, or after - . / _)


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
            fit_math(piece) if is_math else _tex_escape(piece).replace("\u200b", r"\allowbreak{}")
            for is_math, piece in _text_pieces(text)
        )

    def cell(text: str, j: int) -> str:
        if numeric[j]:
            text = _tex_escape(text)
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


def _plain_with_unit(value: str, unit: str) -> str:
    """A value and its unit as a reader sees them: a unit with a power or a formula as
    ``$...$`` math (:func:`unit_text`), which :func:`html_text` and :func:`tex_text` set."""
    if value in ("", "—") or unit in ("", "statement"):
        return value
    if value == "1" and unit in _COUNT_UNITS:  # "1 state", not "1 states"
        unit = unit[:-1]
    return f"{value} {unit_text(unit)}"


#: Plural count units that read in the singular after exactly one (the core's list).
_COUNT_UNITS = COUNT_UNITS


# ---------------------------------------------------------------------------------------
# plain-text math: what reads as program text outside ``$...$``

_GREEK = (
    "alpha|beta|gamma|delta|epsilon|zeta|eta|theta|kappa|lambda|mu|nu|xi|pi|rho|sigma|tau|phi|chi|"
    "psi|omega|Gamma|Delta|Theta|Lambda|Sigma|Phi|Psi|Omega|dtheta|dphi"
)

#: Plain-text math, by kind: what each pattern finds in text outside ``$...$``. One list for the
#: registry's texts (the tests), the docstrings' prose and the text of the built book's pages
#: (the release gate ``tools/check_book.py``), and for :func:`unit_text`, which sets a unit
#: that holds one of them as math.
PLAIN_MATH_PATTERNS = {
    "e-notation": re.compile(r"(?<![\w.])\d+(?:\.\d+)?[eE][+-]?\d+\b"),
    "flat subscript": re.compile(r"\b[A-Za-z]+_[A-Za-z0-9]+\b"),
    "Greek name": re.compile(rf"\b(?:{_GREEK})(?:\d+|_\w+)?\b"),
    "power": re.compile(r"\w\)?\^[-+(\w]|\*\*"),
    "sqrt(": re.compile(r"\bsqrt\("),
    "cross-product bracket": re.compile(r"\[\s*\w+\s+x\s*\]"),
    "(x) product": re.compile(r"\(x\)"),
    "symbol with a flat 0": re.compile(r"\b[A-Za-z]0\b"),
    "derivative quotient": re.compile(r"\bd[A-Za-z]/d[A-Za-z]\b"),
}

#: A starred symbol (``h1*``, the hypothesis :math:`h_1^*`).
PLAIN_STARRED = re.compile(r"(?<![\w\\*])[A-Za-z]\d?\*(?![\w*])")
#: LaTeX source outside math (``tau_{i+1}``, ``e^{+jnv}``, ``\bar``).
PLAIN_LATEX_SOURCE = re.compile(r"\\[A-Za-z]{2,}(?![A-Za-z])|[_^]\{")


def plain_math(text: str) -> list[tuple[str, str]]:
    r"""The plain-text math outside the ``$...$`` spans of ``text``: each hit of
    ``PLAIN_MATH_PATTERNS``, a starred symbol and LaTeX source, as ``(kind, text found)``.

    Parameters
    ----------
    text : str
        A text a reader sees (a note, a quantity, a unit, a page's words), with its math in
        ``$...$``.

    Returns
    -------
    list of (str, str)
        Each hit as its kind (a key of ``PLAIN_MATH_PATTERNS``, ``"starred symbol"`` or
        ``"LaTeX source"``) and the text it found, in the order of the patterns; empty when
        every formula is set as math.

    Examples
    --------
    >>> plain_math("beyond 10 mm/s^2 at rho = 0.25")
    [('Greek name', 'rho'), ('power', 's^2')]
    >>> plain_math(r"beyond 10 $\mathrm{mm/s}^2$ at $\rho = 0.25$")
    []
    """
    found = []
    for is_math, piece in math_spans(text):
        if not is_math:
            found += [
                (kind, m.group(0)) for kind, pat in PLAIN_MATH_PATTERNS.items() for m in pat.finditer(piece)
            ]
            found += [("starred symbol", m.group(0)) for m in PLAIN_STARRED.finditer(piece)]
            found += [("LaTeX source", m.group(0)) for m in PLAIN_LATEX_SOURCE.finditer(piece)]
    return found


#: One atom of a unit: ``sqrt(...)``, a name with an optional subscript (``tau_c``, ``N_T``) and
#: an optional power (``m^3``, ``deg^2``, ``e^*``), or a number with an optional power (``10^8``).
_UNIT_ATOM = re.compile(
    r"sqrt\((?P<root>[^()]+)\)"
    r"|(?P<name>[A-Za-z]+)(?:_(?P<sub>[A-Za-z0-9]+))?(?:\^(?P<pow>[-+]?\w+|\*))?"
    r"|(?P<num>\d+(?:\.\d+)?)(?:\^(?P<npow>[-+]?\w+))?"
)
_GREEK_NAMES = frozenset(_GREEK.split("|")) - {"dtheta", "dphi"}


def _unit_atom_tex(m: re.Match[str], symbol: bool) -> str:
    if m.group("root"):
        return r"\sqrt{" + _unit_tex(m.group("root"), symbol=False) + "}"
    if m.group("num"):
        return m.group("num") + (f"^{{{m.group('npow')}}}" if m.group("npow") else "")
    name, sub, power = m.group("name"), m.group("sub"), m.group("pow")
    if name in _GREEK_NAMES:
        out = "\\" + name
    elif symbol or sub:  # a symbol of a formula (N, N_T): italic
        out = name
    else:  # a unit's symbol (m, s, deg): upright
        out = rf"\mathrm{{{name}}}"
    if sub:
        out += f"_{{{sub}}}"
    if power:
        out += f"^{{{power}}}"
    return out


def _unit_tex(token: str, *, symbol: bool) -> str:
    """A token of a unit (no spaces) as LaTeX math, atom by atom; other characters as they are."""
    out, pos = [], 0
    for m in _UNIT_ATOM.finditer(token):
        out.append(token[pos : m.start()] + _unit_atom_tex(m, symbol))
        pos = m.end()
    return "".join(out) + token[pos:]


_SUPERSCRIPTS = str.maketrans("0123456789-+", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺")
#: An integer power of a unit's symbol or of a number (``m^3``, ``10^8``), and a root of one.
_UNIT_POWER = re.compile(r"(?<=[A-Za-z0-9)])\^([-+]?\d+)(?![\w^])")
_UNIT_ROOT = re.compile(r"\bsqrt\((\w+)\)")


def unit_text(unit: str) -> str:
    r"""A unit as a reader sees it: a power as a superscript, a root as a radical and a unit
    that is a formula as ``$...$`` math; a plain unit (``m/s``, ``dB-Hz``) as it is.

    The ledger keeps units as plain strings (its JSON and CSV exports carry them so); every
    table and text a reader sees shows them through this function, with :func:`html_text` or
    :func:`tex_text`. A unit is rewritten only when it holds plain-text math
    (``PLAIN_MATH_PATTERNS``). A unit of symbols takes its powers and roots as the
    registry's own units write them (``m/s²``, ``deg/h/√Hz``): superscripts and radicals in
    the text, which stays upright and breaks after its slashes as any unit. A unit that is a
    formula, with a Greek letter, a subscript or a symbol standing alone (the :math:`N` of
    :math:`N\tau_{c}/\alpha`), is set as math; its words (``parts in``) stay text.

    Parameters
    ----------
    unit : str
        A claim's or an input's unit, as the registry holds it.

    Returns
    -------
    str
        The unit as text, with ``$...$`` around what is math.

    Examples
    --------
    >>> unit_text("m/s"), unit_text("m^3/s^2"), unit_text("deg^2"), unit_text("rad/s/sqrt(s)")
    ('m/s', 'm³/s²', 'deg²', 'rad/s/√s')
    >>> unit_text("parts in 10^8")
    'parts in 10⁸'
    >>> print(unit_text("N tau_c / alpha"), unit_text("N_T"))
    $N \tau_{c} / \alpha$ $N_{T}$
    """
    if not plain_math(unit):
        return unit
    text = _UNIT_ROOT.sub(r"√\1", _UNIT_POWER.sub(lambda m: m.group(1).translate(_SUPERSCRIPTS), unit))
    if not plain_math(text):
        return text
    tokens = unit.split()
    # a single letter standing alone is a symbol of a formula (the N of N tau_c / alpha)
    formula = any(len(t) == 1 and t.isalpha() for t in tokens)
    runs: list[tuple[bool, list[str]]] = []
    for t in tokens:
        is_word = t.isalpha() and len(t) > 1 and t not in _GREEK_NAMES
        piece = t if is_word else _unit_tex(t, symbol=formula)
        if runs and runs[-1][0] == (not is_word):
            runs[-1][1].append(piece)
        else:
            runs.append((not is_word, [piece]))
    return " ".join(f"${' '.join(ts)}$" if is_math else " ".join(ts) for is_math, ts in runs)


# ---------------------------------------------------------------------------------------
# inline math: ``$...$`` in notes, quantities and errata


_MATH = re.compile(r"(?<![\\$])\$(?=[^\s$])([^$]*?[^\s\\$])\$(?!\$)")


def math_spans(text: str) -> list[tuple[bool, str]]:
    """``text`` cut into ``(is_math, piece)``: ``$...$`` is inline math.

    A dollar sign followed by a space (``50,000 $ INS``) or escaped (``\\$``) is not math,
    so prices and lone dollar signs stay text.

    Parameters
    ----------
    text : str
        A note, quantity or erratum text.

    Returns
    -------
    list of tuple of (bool, str)
        The pieces in order, ``True`` for the inside of a ``$...$`` span (without the dollar
        signs), ``False`` for text.

    Examples
    --------
    >>> math_spans("gain $K_1$ costs 50 $ more")
    [(False, 'gain '), (True, 'K_1'), (False, ' costs 50 $ more')]
    """
    out: list[tuple[bool, str]] = []
    pos = 0
    for m in _MATH.finditer(text):
        if m.start() > pos:
            out.append((False, text[pos : m.start()]))
        out.append((True, m.group(1)))
        pos = m.end()
    if pos < len(text):
        out.append((False, text[pos:]))
    return out


#: A formula of more characters than this (spaces aside) may break in a table of text or a
#: claim row.
_LONG_FORMULA = 12
#: A piece of a claim row's formula longer than this (spaces aside) is also cut inside its
#: parentheses and brackets (about the TeX of what a claim column holds).
_LONG_PIECE = 36
_TEX_TOKEN = re.compile(r"\\[A-Za-z]+|\\.|\s+|.", re.S)
#: TeX breaks inline math after a relation or a binary operator at the formula's outer level
_TEX_RELATIONS = frozenset(
    ["=", "<", ">", r"\le", r"\leq", r"\ge", r"\geq", r"\ne", r"\neq", r"\approx", r"\sim",
     r"\simeq", r"\equiv", r"\propto", r"\to", r"\rightarrow", r"\ll", r"\gg"]
)  # fmt: skip
_TEX_BINARY = frozenset(["+", "-", r"\pm", r"\mp", r"\times", r"\cdot"])
_TEX_OPEN = frozenset(["(", "[", r"\{", r"\langle", r"\lvert", r"\lVert"])
_TEX_CLOSE = frozenset([")", "]", r"\}", r"\rangle", r"\rvert", r"\rVert"])
_TEX_BARS = frozenset(["|", r"\|", r"\vert", r"\Vert"])


def _math_breaks(tex: str, *, brackets: bool = False) -> list[str]:
    r"""A long inline formula cut where TeX may break it in a paragraph: after a relation or a
    binary operator at its outer level (not inside braces, brackets or bars; with
    ``brackets``, inside the outermost plain parentheses and brackets too, as TeX also may).

    MathJax 3 never breaks an inline formula, so in a table of text one long formula sets
    the least width of its column however the words around it wrap. Each piece but the last
    ends with an empty group, so that its operator keeps the spacing it has between two
    operands; the pieces set side by side read as the whole formula. A formula of at most
    ``_LONG_FORMULA`` characters, and a last piece of fewer than three, stay whole.

    Examples
    --------
    >>> _math_breaks(r"\mathrm{Exp}_g = a^2/(2p)")
    ['\\mathrm{Exp}_g ={}', 'a^2/(2p)']
    >>> _math_breaks(r"C/N_0 - 10\log_{10} B_L")
    ['C/N_0 -{}', '10\\log_{10} B_L']
    >>> _math_breaks(r"|\ln \mathrm{bound} - \ln p_f|"), _math_breaks("P_{DL} = 0.999")
    (['|\\ln \\mathrm{bound} - \\ln p_f|'], ['P_{DL} = 0.999'])
    >>> _math_breaks(r"\left| a - b \right| = -c + d^{-1}")
    ['\\left| a - b \\right| ={}', '-c +{}', 'd^{-1}']
    >>> _math_breaks(r"[a(k-1) + b_1 + c_2]^{-1}", brackets=True)
    ['[a(k-1) +{}', 'b_1 +{}', 'c_2]^{-1}']
    >>> _math_breaks(r"E[x] = \begin{cases} a, & i = 0 \\ b, & i > 0 \end{cases}")
    ['E[x] ={}', '\\begin{cases} a, & i = 0 \\\\ b, & i > 0 \\end{cases}']
    """
    if len(re.sub(r"\s", "", tex)) <= _LONG_FORMULA:
        return [tex]
    cuts: list[int] = []
    braces, fences, environments, depth = 0, [], 0, 0
    prev = ""  # the previous token at the outer level ("" at the start)
    delimiter = False  # the token after \left or \right
    for m in _TEX_TOKEN.finditer(tex):
        tok = m.group(0)
        if tok.isspace():
            continue
        if delimiter:
            delimiter = False
            continue
        # a matrix or cases environment is one unit: never cut inside it
        environments += {r"\begin": 1, r"\end": -1}.get(tok, 0)
        if environments or tok == r"\end":
            prev = "}"
            continue
        braces += {"{": 1, "}": -1}.get(tok, 0)
        if braces or tok == "}":
            prev = "}"
            continue
        if tok in (r"\left", r"\right"):
            if tok == r"\left":
                fences.append(tok)
            elif fences:
                fences.pop()
            delimiter, prev = True, ")"
            continue
        if brackets and tok in ("(", "[", ")", "]"):  # cut inside the outermost pair only
            depth += 1 if tok in "([" else -1
            prev = "(" if tok in "([" else ")"
            continue
        if brackets and depth > 1:
            prev = tok
            continue
        if tok in _TEX_OPEN or (tok in _TEX_BARS and not (fences and fences[-1] == tok)):
            fences.append(tok)
            prev = "("
            continue
        if tok in _TEX_CLOSE or tok in _TEX_BARS:
            if fences:
                fences.pop()
            prev = ")"
            continue
        operators = _TEX_RELATIONS | _TEX_BINARY
        operand_before = prev and prev not in ("(", "^", "_", ",") and prev not in operators
        if not fences and operand_before and tok in operators:
            cuts.append(m.end())
        prev = tok
    pieces, start = [], 0
    for cut in cuts:
        if len(re.sub(r"\s", "", tex[cut:])) >= 3:
            pieces.append(tex[start:cut].strip() + "{}")
            start = cut
    return [*pieces, tex[start:].strip()]


def html_text(text: str, *, wide: int = 0) -> str:
    r"""Escaped HTML with ``$...$`` as MathJax inline math, marked up as Sphinx does.

    Parameters
    ----------
    text : str
        A note, quantity or erratum text (:func:`math_spans` says what is math).
    wide : int, optional
        A math piece longer than this many characters is wrapped in a
        ``<span class="ledger-math-wide">`` (0: never), so that one long formula does not
        widen its column past the page: it is cut where TeX may break it (after a relation or
        a binary operator at its outer level), its pieces joined by line-break opportunities,
        so that it wraps inside its box; a piece still wider than the box is set smaller by
        the book's equation fitting, and scrolls inside the box only beyond that.

    Returns
    -------
    str
        The text HTML-escaped, each math piece escaped inside ``\(...\)`` in a
        ``<span class="math notranslate nohighlight">``.

    Examples
    --------
    >>> print(html_text("gain $K_1 < 2$ & more"))
    gain <span class="math notranslate nohighlight">\(K_1 &lt; 2\)</span> &amp; more
    >>> print(html_text("$x = a + b$", wide=5))
    <span class="ledger-math-wide"><span class="math notranslate nohighlight">\(x = a + b\)</span></span>
    >>> out = html_text("$x_{\\rm long} = a + b$", wide=5)
    >>> print(out.replace(' class="math notranslate nohighlight"', ""))
    <span class="ledger-math-wide"><span>\(x_{\rm long} ={}\)</span><wbr><span>\(a + b\)</span></span>
    """
    out = []
    for is_math, piece in math_spans(text):
        out.append(_math_html(piece, wide) if is_math else html.escape(piece))
    return "".join(out)


def _math_html(piece: str, wide: int) -> str:
    r"""A formula as MathJax inline math; one longer than ``wide`` characters (``wide`` > 0) in
    a ``ledger-math-wide`` box, cut where TeX may break it (:func:`_math_breaks`).

    Examples
    --------
    >>> print(_math_html("K_1", 24))
    <span class="math notranslate nohighlight">\(K_1\)</span>
    """
    span = '<span class="math notranslate nohighlight">\\({}\\)</span>'
    if not wide or len(piece) <= wide:
        return span.format(html.escape(piece))
    pieces = "<wbr>".join(span.format(html.escape(p)) for p in _math_parts(piece))
    return f'<span class="ledger-math-wide">{pieces}</span>'


def _math_parts(piece: str) -> list[str]:
    r"""The pieces a long formula of a claim row is cut into (:func:`_math_html`): where TeX may
    break it, and a piece still longer than a claim column holds inside its brackets too.

    Examples
    --------
    >>> _math_parts(r"x_{\rm long} = a + b")
    ['x_{\\rm long} ={}', 'a + b']
    """
    return [
        q
        for p in _math_breaks(piece)
        for q in (_math_breaks(p, brackets=True) if len(re.sub(r"\s", "", p)) > _LONG_PIECE else [p])
    ]


# ---------------------------------------------------------------------------------------
# how wide a formula sets: a rule that does not depend on the browser

#: Widths in em of what inline TeX math sets (Computer Modern's metrics, rounded): an
#: italic letter, a capital, a digit, a Greek letter, a fence, a relation and a binary
#: operator with the spaces TeX puts around them, a named operator's letter.
_EM = {
    "letter": 0.52, "capital": 0.75, "digit": 0.5, "greek": 0.58, "Greek": 0.72, "fence": 0.39,
    "relation": 1.33, "binary": 1.22, "sign": 0.78, "comma": 0.45, "thin": 0.28, "text": 0.5,
    "space": 0.25, "script": 0.71, "frac": 0.24, "sqrt": 0.85, "delimiter": 0.45, "other": 0.6,
}  # fmt: skip
_EM_SPACES = {
    r"\,": 0.17, r"\:": 0.22, r"\;": 0.28, r"\ ": 0.25, r"\!": -0.17, r"\quad": 1.0, r"\qquad": 2.0,
}  # fmt: skip
_EM_FONTS = {
    r"\mathbf": 1.1, r"\boldsymbol": 1.1, r"\bm": 1.1, r"\mathrm": 0.95, r"\mathcal": 1.2, r"\mathbb": 1.2,
}  # fmt: skip
#: symbols of their own widths (a large operator with the thin space after it)
_EM_SYMBOLS = {
    r"\ldots": 1.17, r"\cdots": 1.17, r"\dots": 1.17, r"\infty": 1.0, r"\partial": 0.57, r"\nabla": 0.83,
    r"\ell": 0.42, r"\prime": 0.28, r"\{": 0.5, r"\}": 0.5, r"\|": 0.5, r"\langle": 0.39, r"\rangle": 0.39,
    r"\vert": 0.28, r"\Vert": 0.5, r"\%": 0.83, r"\sum": 1.22, r"\prod": 1.12, r"\bigcap": 1.02,
    r"\bigcup": 1.02, r"\int": 0.77, r"|": 0.28, "/": 0.5, ".": 0.28, "!": 0.28,
}  # fmt: skip
_EM_TEXT = frozenset([r"\text", r"\textrm", r"\mbox", r"\textit", r"\textbf", r"\operatorname"])
_EM_ACCENTS = frozenset([r"\hat", r"\bar", r"\tilde", r"\dot", r"\ddot", r"\vec", r"\widehat", r"\overline"])
_EM_NAMED = frozenset(
    [r"\exp", r"\ln", r"\log", r"\sin", r"\cos", r"\tan", r"\arctan", r"\min", r"\max", r"\det", r"\lim",
     r"\sup", r"\inf", r"\tr", r"\sinh", r"\cosh", r"\tanh", r"\arg", r"\Pr"]
)  # fmt: skip
_EM_GREEK_CAPITALS = frozenset(
    [r"\Gamma", r"\Delta", r"\Theta", r"\Lambda", r"\Xi", r"\Pi", r"\Sigma", r"\Phi", r"\Psi", r"\Omega"]
)
_EM_BIG = frozenset(
    [r"\left", r"\right", r"\big", r"\Big", r"\bigg", r"\Bigg", r"\bigl", r"\bigr", r"\Bigl", r"\Bigr"]
)
_EM_FENCES = {"bmatrix": 0.9, "pmatrix": 0.9, "vmatrix": 0.6, "Bmatrix": 1.0, "cases": 0.6}


def _text_em(text: str) -> float:
    return sum(_EM["space"] if ch == " " else 0.72 if ch.isupper() else _EM["text"] for ch in text)


def math_em(tex: str) -> float:
    r"""About how wide a formula sets as inline TeX math, in em of its font, from its source
    alone (no browser): each symbol's width from Computer Modern's metrics, a script at 71 %,
    a fraction as wide as its wider part at script size, a matrix or cases environment as its
    columns' widest cells side by side, the spaces TeX puts around relations and operators.

    A rough measure (MathJax sets the claim rows' formulas 1.18 to 1.5 times wider than this,
    in em of the table's text, median 1.35, over every formula the claim tables quote): it
    ranks formulas by width, which is what :func:`quote_below` needs.

    Examples
    --------
    >>> math_em("x"), math_em("x = 1")
    (0.52, 2.35)
    >>> round(math_em(r"\frac{a}{b}"), 2), round(math_em(r"x^{2}"), 3)
    (0.61, 0.925)
    >>> round(math_em(r"\begin{bmatrix} a & b \\ c & d \end{bmatrix}"), 2)
    3.27
    """
    toks = [t for t in _TEX_TOKEN.findall(tex) if not t.isspace()]
    pos = 0

    def argument() -> list[str]:  # a {group} or one token
        nonlocal pos
        if pos >= len(toks):
            return []
        if toks[pos] != "{":
            pos += 1
            return [toks[pos - 1]]
        depth, start = 0, pos
        while pos < len(toks):
            depth += {"{": 1, "}": -1}.get(toks[pos], 0)
            pos += 1
            if depth == 0:
                break
        return toks[start + 1 : pos - 1]

    def em(ts: list[str]) -> float:
        return math_em(" ".join(ts))

    def scripts(base: float) -> float:  # a base with the scripts after it
        nonlocal pos
        sup = sub = 0.0
        while pos < len(toks) and toks[pos] in ("^", "_", "'"):
            pos += 1
            if toks[pos - 1] == "'":
                sup += _EM["thin"]
            elif toks[pos - 1] == "^":
                sup = max(sup, _EM["script"] * em(argument()))
            else:
                sub = max(sub, _EM["script"] * em(argument()))
        return base + (max(sup, sub) + 0.05 if sup or sub else 0.0)

    def environment(name: str) -> float:  # columns side by side, 1 em apart
        nonlocal pos
        depth, start = 1, pos
        while pos < len(toks) and depth:
            depth += {r"\begin": 1, r"\end": -1}.get(toks[pos], 0)
            pos += 1
        body = toks[start : pos - 1]
        argument()  # the environment's name after \end
        rows: list[list[list[str]]] = [[[]]]
        depth = 0
        for t in body:
            depth += {"{": 1, "}": -1, r"\begin": 1, r"\end": -1}.get(t, 0)
            if depth == 0 and t == "&":
                rows[-1].append([])
            elif depth == 0 and t == r"\\":
                rows.append([[]])
            else:
                rows[-1][-1].append(t)
        ncol = max(len(row) for row in rows)
        cols = [max(em(row[j]) if j < len(row) else 0.0 for row in rows) for j in range(ncol)]
        return sum(cols) + (ncol - 1) + _EM_FENCES.get(name, 0.0) + (0.33 if name != "matrix" else 0.0)

    width, operand = 0.0, False  # operand: the token before was an operand (a sign is binary)
    while pos < len(toks):
        t = toks[pos]
        pos += 1
        if t == "{":
            pos -= 1
            width += scripts(em(argument()))
        elif t == r"\begin":
            width += environment("".join(argument()))
        elif t in (r"\frac", r"\tfrac", r"\dfrac"):
            parts = max(em(argument()), em(argument()))
            width += scripts((1.0 if t == r"\dfrac" else _EM["script"]) * parts + _EM["frac"])
        elif t == r"\sqrt":
            width += scripts(em(argument()) + _EM["sqrt"])
        elif t == r"\substack":
            rows: list[list[str]] = []
            row: list[str] = []
            for s in argument():
                if s == r"\\":
                    rows.append(row)
                    row = []
                else:
                    row.append(s)
            width += max(em(r) for r in [*rows, row])
        elif t in _EM_BIG:
            width += scripts(0.12 if pos < len(toks) and toks[pos] == "." else _EM["delimiter"])
            pos += 1
        elif t in _EM_TEXT:
            width += scripts(_text_em("".join(argument())) + (0.17 if t == r"\operatorname" else 0.0))
        elif t in _EM_FONTS:
            width += scripts(_EM_FONTS[t] * em(argument()))
        elif t in _EM_ACCENTS:
            width += scripts(em(argument()))
        elif t in _EM_NAMED:
            width += scripts(_EM["text"] * (len(t) - 1)) + 0.17
        elif t in _EM_SPACES:
            width += _EM_SPACES[t]
        elif t in _TEX_RELATIONS:
            width += _EM["relation"] if operand else 1.05
        elif t in _TEX_BINARY:
            width += _EM["binary"] if operand else _EM["sign"]
            operand = False
            continue
        elif t in (",", ";"):
            width += _EM["comma"]
        elif t in ("(", "[", ")", "]"):
            width += scripts(_EM["fence"])
            operand = t in ")]"
            continue
        elif t in ("^", "_", "'"):
            pos -= 1
            width += scripts(0.0)
        elif t in _EM_SYMBOLS:
            width += scripts(_EM_SYMBOLS[t])
        elif t in _EM_GREEK_CAPITALS:
            width += scripts(_EM["Greek"])
        elif t.startswith("\\") and len(t) > 2:
            width += scripts(_EM["greek"])
        elif t.isdigit():
            width += scripts(_EM["digit"])
        elif t.isalpha():
            width += scripts(_EM["capital"] if t.isupper() else _EM["letter"])
        elif t not in ("&", r"\\", "}"):
            width += scripts(_EM["other"])
        operand = True
    return width


def tex_text(text: str) -> str:
    r"""Escaped LaTeX with ``$...$`` passed through as math.

    Parameters
    ----------
    text : str
        A note, quantity or erratum text (:func:`math_spans` says what is math).

    Returns
    -------
    str
        The text with LaTeX's special characters escaped outside the math, and each math
        piece as written between dollar signs.

    Examples
    --------
    >>> print(tex_text("50% of $K_1$"))
    50\% of $K_1$
    """
    return "".join(f"${piece}$" if is_math else _tex_escape(piece) for is_math, piece in math_spans(text))


# ---------------------------------------------------------------------------------------
# the chapters' claim tables

_GROUP_PATTERNS = (
    r"\bTables?\s+[A-Z]?\d+(?:\.\d+)*",
    r"\bFigs?\.\s+\d+(?:\.\d+)*(?:\s*-\s*\d+(?:\.\d+)*)?",
    r"\bTheorem(?:\s+\d+(?:\.\d+)*)?",
    r"\bRemark\s+\([ivx]+\)",
    r"\bProposition\b",
    r"\bEqs?\.\s+\([^)]*\)(?:\s*-\s*\([^)]*\))?",
    r"\b(?:Appendix|App\.)\s+[A-Z]\b",
    r"\bSecs?\.\s+(?:[IVX]+(?:\.[A-Z0-9]+)*|\d+(?:\.\d+)*)",
)


def claim_group(locator: str) -> str:
    """What a claim checks, from its locator: the table, figure, theorem, equation, appendix
    or section it names (in that order of preference).

    ``"Table 2.6, column 2"`` -> ``"Table 2.6"``; ``"Sec. 3.6, discussion of Fig. 5"`` ->
    ``"Fig. 5"``; ``"Sec. III, after Eq. (9)"`` -> ``"Eq. (9)"``; a locator naming none of
    them is its own group.

    Parameters
    ----------
    locator : str
        A claim's locator, in the paper's words.

    Returns
    -------
    str
        The group's label: the first table, figure, theorem, remark, proposition, equation,
        appendix or section named, else the locator without surrounding spaces.

    Examples
    --------
    >>> claim_group("Table 2.6, column 2"), claim_group("Sec. 3.6, discussion of Fig. 5")
    ('Table 2.6', 'Fig. 5')
    >>> claim_group("abstract")
    'abstract'
    """
    for pattern in _GROUP_PATTERNS:
        m = re.search(pattern, locator)
        if m:
            return m.group(0)
    return locator.strip()


def _is_truth(value: Any) -> bool:
    """A Python or numpy boolean (:func:`navcore.ledger.core._is_truth`, its one home)."""
    return _core_is_truth(value)


def _statement_word(value: Any, *, printed: bool) -> str:
    """Words for a truth value: printed ``stated`` (``stated not to hold`` for a printed
    falsehood), reproduced ``holds`` / ``does not hold``."""
    if printed:
        return "stated" if value else "stated not to hold"
    return "holds" if value else "does not hold"


def _printed_text(e: Evaluation) -> str:
    """What the paper printed: its words as the claim quotes them; else the number as printed
    with its relation and unit, or "stated" for a statement the book checks."""
    c = e.claim
    quote, source = claim_quote(c, e.tolerance)
    if source == "claim":
        return quote
    if _is_truth(c.published):
        return _statement_word(c.published, printed=True)
    rel = "" if c.relation == "=" else c.relation.replace(">=", "≥").replace("<=", "≤") + " "
    return _plain_with_unit(rel + format_value(c.published), c.unit)


def soft_hyphens(text: str) -> str:
    """``text`` with a soft hyphen (``&shy;``) at each syllable break of the long words the
    ledger's narrow columns hold (:data:`_SOFT_HYPHENS`: verdicts, kinds, and the papers' locator
    words, "Appendix" among them, wider than the interactive ledger's locator column at 1400 px);
    a browser breaks such a word there, with a hyphen, only where it does not fit its column,
    instead of at the column's edge. Other words are left as they are.

    Examples
    --------
    >>> soft_hyphens("Appendix E, (E.1)")
    'Ap&shy;pen&shy;dix E, (E.1)'
    >>> soft_hyphens("Sec. 2.5 (acquisition)")
    'Sec. 2.5 (ac&shy;qui&shy;si&shy;tion)'
    >>> soft_hyphens("Eq. (3)")
    'Eq. (3)'
    """
    return re.sub(r"[A-Za-z]{7,}", lambda m: _SOFT_HYPHENS.get(m.group(0), m.group(0)), text)


#: A formula longer than this many characters is set in a box scaled to its table column
#: when wider than it (:func:`fit_math`); a shorter one as inline math.
_FIT_MATH_CHARS = 24

#: An erratum's formula longer than this many characters of TeX is set in a box of its own,
#: cut where TeX may break it (:func:`html_text`), so that a corrected equation wraps on a
#: phone instead of running past the text column; shorter ones stay inline in the sentence.
_ERRATUM_WIDE_MATH = 40

#: The LaTeX macro :func:`fit_math` calls, defined in the book's preamble (``_config.yml``) and
#: in the verification reports' (:mod:`navcore.report`); it needs graphicx. The formula is set
#: as inline math in a box, scaled down to the line width (a table cell's column) only when
#: wider than it, so that a narrow column holds a long formula without an overfull box.
FIT_MATH_PREAMBLE = (
    r"\newsavebox{\navcorefitbox}"
    r"\newcommand{\navcorefitmath}[1]{\sbox{\navcorefitbox}{$#1$}"
    r"\ifdim\wd\navcorefitbox>\linewidth\resizebox{\linewidth}{!}{\usebox{\navcorefitbox}}"
    r"\else\usebox{\navcorefitbox}\fi}"
)


def fit_math(piece: str) -> str:
    r"""A formula of a printed table cell as LaTeX math: inline if short, else in a box scaled
    down to its column only when wider than it (:data:`FIT_MATH_PREAMBLE`).

    Parameters
    ----------
    piece : str
        The formula, without its dollar signs.

    Returns
    -------
    str
        ``$piece$``, or ``\navcorefitmath{piece}`` for a formula longer than 24 characters.

    Examples
    --------
    >>> print(fit_math("K_1"))
    $K_1$
    >>> print(fit_math("\\sigma_{\\xi\\tau_0}^2 = \\sigma^2 \\gamma_0 + \\sigma^2 \\gamma_1"))
    \navcorefitmath{\sigma_{\xi\tau_0}^2 = \sigma^2 \gamma_0 + \sigma^2 \gamma_1}
    """
    return f"${piece}$" if len(piece) <= _FIT_MATH_CHARS else r"\navcorefitmath{" + piece + "}"


_DISPLAY = re.compile(r"\$\$(.*?)\$\$", re.S)
_EQ_NUMBER = re.compile(r"\\(?:quad|qquad)\s*\(?(?:\\text\{[\w.]+\}|[\w.]+)\)?\s*$|\\tag\{[^}]*\}")
_MATH_TOKEN = re.compile(r"\\(?:begin|end)\{[^}]*\}|\\(?:left|right)(?![A-Za-z])|\\[A-Za-z]+|\\.|[{}&]")

#: Unicode a quote's formulas use, as math commands (the PDF's math fonts are not Unicode).
_TEX_MATH_CHARS = {
    "×": r"\times ",
    "·": r"\cdot ",
    "≤": r"\leq ",
    "≥": r"\geq ",
    "≈": r"\approx ",
    "−": "-",
    **{
        ch: "\\" + name + " "
        for ch, name in zip(
            "αβγδεθλμνξπρστφχψωΓΔΘΛΞΠΣΦΨΩ",
            "alpha beta gamma delta epsilon theta lambda mu nu xi pi rho sigma tau phi chi psi "
            "omega Gamma Delta Theta Lambda Xi Pi Sigma Phi Psi Omega".split(),
            strict=True,
        )
    },
}


def quote_math(piece: str) -> str:
    r"""A formula of a quote made whole for typesetting: a quote may cut a displayed equation
    (the transcription's alignment ``&``, a matrix's rows, an open ``\left`` or brace).

    The equation number (``\tag{..}``, ``\quad (3)``) is left out; a matrix fragment (rows
    ``\\`` outside an environment) is set as a matrix, and an alignment ``&`` outside one is
    dropped; a ``\left`` or ``\right`` without its partner is closed by an empty delimiter and
    an open brace by an ellipsis and its brace, so that the formula typesets as far as the
    paper's words go. The symbols stay the paper's.

    Parameters
    ----------
    piece : str
        The formula, without its dollar signs.

    Returns
    -------
    str
        The formula, typesettable by MathJax and LaTeX (Unicode letters and operators such as
        ``σ`` and ``×``, which the PDF's math fonts lack, as math commands).

    Examples
    --------
    >>> quote_math(r"\gamma_n &= \frac{a}{b} \tag{4.5.31}")
    '\\gamma_n = \\frac{a}{b}'
    >>> quote_math(r"\exp \left[(K t + 1) \ln")
    '\\exp \\left[(K t + 1) \\ln\\right.'
    >>> quote_math(r"\sqrt{2 \frac{\partial^2}{\partial r^2}")
    '\\sqrt{2 \\frac{\\partial^2}{\\partial r^2}\\ldots}'
    >>> quote_math(r"a & b \\ c & d")
    '\\begin{matrix}a & b \\\\ c & d\\end{matrix}'
    >>> quote_math(r"\sum_{\substack{j=1 \\ j \neq i}}^N x_j")
    '\\sum_{\\substack{j=1 \\\\ j \\neq i}}^N x_j'
    >>> quote_math("1.61×10^{-4}")
    '1.61\\times 10^{-4}'
    """
    piece = _EQ_NUMBER.sub("", piece).strip()
    depth, stack, lead, amps = 0, [], [], []
    rows = False
    for m in _MATH_TOKEN.finditer(piece):
        tok = m.group(0)
        if tok.startswith("\\begin"):
            depth += 1
        elif tok.startswith("\\end"):
            depth -= 1
        elif tok in ("{", "\\left"):
            stack.append(tok)
        elif tok in ("}", "\\right"):
            if stack and stack[-1] == ("{" if tok == "}" else "\\left"):
                stack.pop()
            else:
                lead.append("{" if tok == "}" else "\\left.")
        elif depth == 0 and "{" not in stack and tok == "&":
            amps.append(m.start())
        elif depth == 0 and "{" not in stack and tok == "\\\\":  # not a \substack's lines
            rows = True
    if amps and not rows:  # an alignment point of the paper's display: no alignment inline
        piece = "".join(ch for i, ch in enumerate(piece) if i not in amps)
    tail = "".join("}" if tok == "{" else "\\right." for tok in reversed(stack))
    if "{" in stack:
        tail = "\\ldots" + tail
    piece = "".join(reversed(lead)) + re.sub(r"\s{2,}", " ", piece) + tail
    if rows:
        piece = "\\begin{matrix}" + piece + "\\end{matrix}"
    return "".join(_TEX_MATH_CHARS.get(ch, ch) for ch in piece).strip()


def quote_text(text: str) -> str:
    r"""A quote of the paper with every formula as inline ``$...$`` math made whole
    (:func:`quote_math`): a display formula inline and unnumbered, a cut one closed.

    Parameters
    ----------
    text : str
        A claim's quote (its ``printed``), whose ``$...$`` and ``$$...$$`` are its formulas.

    Returns
    -------
    str
        The quote's words as they are and each formula as ``$...$``.

    Examples
    --------
    >>> print(quote_text("so that $$x &= 1 \\quad (3)$$ holds for $p_d$"))
    so that $x = 1$ holds for $p_d$
    """
    text = _DISPLAY.sub(lambda m: "$" + m.group(1).strip() + "$", text)
    return "".join(f"${quote_math(piece)}$" if is_math else piece for is_math, piece in math_spans(text))


#: A dollar sign of the paper's words in HTML, which MathJax leaves as it is.
_HTML_DOLLAR = '<span class="tex2jax_ignore mathjax_ignore">$</span>'


#: A power in a quote's words (``5 parts in 10^8``, ``e^*``): the transcription's mark for a
#: superscript, set as math by :func:`_quote_markup`.
_QUOTE_POWER = re.compile(r"(?<![\w^\\])(\w+)\^([-+]?\d+|\w|\*)(?![\w^])")
#: A quote's emphasis as the transcription marks it: ``**word**`` (strong), ``*word*``.
_QUOTE_EMPHASIS = re.compile(
    r"\*\*(?=\S)(?P<strong>.+?)(?<=\S)\*\*|(?<![\w*])\*(?=[^\s*])(?P<em>[^*]+?)(?<=[^\s*])\*(?![\w*])"
)


def _quote_markup(text: str) -> str:
    """A quote with each power its words mark (``10^8``) as ``$...$`` math, the rest as it is.

    Examples
    --------
    >>> print(_quote_markup("better than 5 parts in 10^8, is e^* and $x^2$"))
    better than 5 parts in $10^{8}$, is $e^{*}$ and $x^2$
    """
    return "".join(
        f"${piece}$" if is_math else _QUOTE_POWER.sub(r"$\1^{\2}$", piece)
        for is_math, piece in math_spans(text)
    )


def _emphasis(text: str, escape: Any, strong: str, em: str) -> str:
    """A quote's words escaped by ``escape``, with its marked emphasis (``**word**``,
    ``*word*``) set by the templates ``strong`` and ``em`` (``{}``: the escaped words).

    Examples
    --------
    >>> _emphasis("the detector **deteriorates**, *a priori*", html.escape, "<b>{}</b>", "<em>{}</em>")
    'the detector <b>deteriorates</b>, <em>a priori</em>'
    """
    out, pos = [], 0
    for m in _QUOTE_EMPHASIS.finditer(text):
        out.append(escape(text[pos : m.start()]))
        out.append((strong if m.group("strong") else em).format(escape(m.group("strong") or m.group("em"))))
        pos = m.end()
    return "".join(out) + escape(text[pos:])


def _latex_source(piece: str) -> bool:
    """Whether a piece of a quote outside its math is LaTeX source (a backslash other than an
    escaped dollar sign, ``\\$``, which is the paper's own)."""
    return "\\" in piece.replace("\\$", "")


def _printed_tex(text: str) -> str:
    r"""The Printed cell of a PDF claim table: the paper's words as text, its formulas as math
    (a long one scaled down to the column when wider than it, :func:`fit_math`; a display
    formula inline, without its equation number), and LaTeX transcribed without math
    delimiters as small source text that may break anywhere, so that a narrow column never
    runs over.

    Examples
    --------
    >>> print(_printed_tex("about $10^{-6}$ of it"))
    about $10^{-6}$ of it
    >>> long = "$$\\frac{2\\pi}{\\lambda}\\left(l_{t}^{(m),n} - l_{t}^{(n),n}\\right)^T x \\quad (17)$$"
    >>> print(_printed_tex(long))
    \navcorefitmath{\frac{2\pi}{\lambda}\left(l_{t}^{(m),n} - l_{t}^{(n),n}\right)^T x}
    >>> "\\ttfamily" in _printed_tex("\\mathbf{P}_N \\mathbf{P}_N^T = \\sigma_N^2 \\mathbf{I}")
    True
    """
    text = _DISPLAY.sub(lambda m: "$" + _EQ_NUMBER.sub("", m.group(1)).strip() + "$", text)
    pieces = math_spans(text)
    if any(_latex_source(piece) for is_math, piece in pieces if not is_math):  # LaTeX without delimiters
        return r"{\scriptsize\ttfamily " + _tex_breakable(text) + "}"
    out = []
    for is_math, piece in math_spans(_quote_markup(text)):
        out.append(
            fit_math(quote_math(piece))
            if is_math
            else _emphasis(piece.replace("\\$", "$"), _tex_breakable, r"\textbf{{{}}}", r"\emph{{{}}}")
        )
    return "".join(out)


def _printed_html(text: str, *, fold: int = 0) -> str:
    r"""The Printed cell of an HTML claim table: the paper's words as text and its formulas as
    MathJax math (a display formula inline, without its equation number), a long formula in a
    box of its own, cut where TeX may break it so that it wraps in a narrow column
    (:func:`_math_html`), and LaTeX transcribed without math delimiters as small source text
    that may break anywhere. A short value stays on one line.

    Parameters
    ----------
    text : str
        What the paper printed (:func:`_printed_text`).
    fold : int, optional
        A quote longer than this many characters is folded behind a "quote" disclosure
        (0: never), so that a narrow column is not a long thin paragraph; so is a shorter one
        that the interactive ledger's Printed column cannot hold (:func:`_fits_printed_column`).

    Examples
    --------
    >>> print(_printed_html("about 10 m"))
    about&nbsp;10&nbsp;m
    >>> print(_printed_html("$$x = 1 \\quad (3)$$"))
    <span class="math notranslate nohighlight">\(x = 1\)</span>
    >>> "<details" in _printed_html("a long sentence the paper printed, word for word", fold=20)
    True
    >>> [_printed_html(q, fold=40).startswith("<details") for q in ("$p = 50$", "$y = (G'G)^{-1}G'z$")]
    [False, True]
    """
    if len(text) <= 16 and not any(ch in text for ch in "$\\^*"):
        return _nowrap(text)
    text = _DISPLAY.sub(lambda m: "$" + _EQ_NUMBER.sub("", m.group(1)).strip() + "$", text)
    pieces = math_spans(text)
    if any(_latex_source(piece) for is_math, piece in pieces if not is_math):  # LaTeX without delimiters
        body = f'<code class="ledger-latex">{html.escape(text)}</code>'
    else:
        out = []
        for is_math, piece in math_spans(_quote_markup(text)):
            if not is_math:  # a dollar sign of the paper's (a price) is not a math delimiter
                out.append(
                    _emphasis(piece, html.escape, "<strong>{}</strong>", "<em>{}</em>").replace(
                        "\\$", _HTML_DOLLAR
                    )
                )
                continue
            out.append(_math_html(quote_math(piece), _FIT_MATH_CHARS))
        body = "".join(out)
    if fold and (len(text) > fold or not _fits_printed_column(text)):
        return f'<details class="ledger-quote"><summary>quote</summary>{body}</details>'
    return body


#: The interactive ledger's Printed column is about 55 px wide at 1400 px (8 % of its table): a
#: word of more than this many characters breaks inside itself there ("resultin-g")...
_PRINTED_COLUMN_WORD = 8
#: ... and it holds a formula of about 5.7 em as MathJax sets it at the equation fitting's 70 %,
#: which :func:`math_em` puts at 3.3 to 4.8 em (MathJax sets 1.18 to 1.75 times its measure;
#: ``\text{Exp}g = 12.5``, 3.57 em here, sets 85 px and was cut in its 55 px box, December 2026).
_PRINTED_COLUMN_MATH_EM = 3.0


def _fits_printed_column(text: str) -> bool:
    r"""Whether a short quote can stand unfolded in the interactive ledger's narrow Printed
    column: no word longer than :data:`_PRINTED_COLUMN_WORD` characters and no formula whose
    widest unbreakable piece is wider than :data:`_PRINTED_COLUMN_MATH_EM` by :func:`math_em`.

    Examples
    --------
    >>> _fits_printed_column("282 ft"), _fits_printed_column("The resulting error statistics")
    (True, False)
    >>> _fits_printed_column("Appendix G"), _fits_printed_column("Appendices")
    (True, False)
    >>> _fits_printed_column("$p = 50$"), _fits_printed_column(r"$\text{Exp}g = 12.5$")
    (True, False)
    """
    words, wide = [], 0.0
    for is_math, piece in math_spans(text):
        if is_math:
            wide = max(wide, *(math_em(part) for part in _math_parts(quote_math(piece))))
        else:
            words += piece.split()
    return wide <= _PRINTED_COLUMN_MATH_EM and all(len(w) <= _PRINTED_COLUMN_WORD for w in words)


#: A quoted formula whose widest unbreakable piece sets wider than this (:func:`math_em`) does
#: not fit the Printed column even set at 70 % (its box is 16 em of the table's text, so 22.9
#: em of it at 70 %; MathJax sets 1.18 to 1.5 times :func:`math_em`, median 1.35). Calibrated
#: on every formula the claim tables quoted (December 2026): the seven that scrolled in their
#: box measure 19.1 to 31.8 em here (26 to 43 em of text as set), the widest of those that fit
#: 16.2 em (21.8 em as set); 17.5 lies between, so that none of those that fit moves.
_QUOTE_BELOW_EM = 17.5


def quote_below(text: str) -> bool:
    r"""Whether a claim's printed quote is shown in a full-width line under its claim's row (in
    the Printed column, "the equation below"): a formula of it that cannot be cut where TeX
    may break it into pieces the column holds, its widest piece (:func:`_math_parts`) wider
    than 17.5 em by :func:`math_em`, a measure of the formula's source alone, so that the
    layout does not depend on the browser.

    Parameters
    ----------
    text : str
        What the paper printed (:func:`_printed_text`).

    Returns
    -------
    bool
        True if the quote goes under its claim's row.

    Examples
    --------
    >>> quote_below("$$x = a + b \\quad (3)$$"), quote_below("about 10 m")
    (False, False)
    >>> quote_below("$$(G'P_n^{-1}G)^{-1}G'P_n^{-1}FP_{\\xi_x}F'P_n^{-1}G(G'P_n^{-1}G)^{-1}$$")
    True
    """
    text = _DISPLAY.sub(lambda m: "$" + _EQ_NUMBER.sub("", m.group(1)).strip() + "$", text)
    pieces = math_spans(text)
    if not any(is_math for is_math, _ in pieces) or any(
        _latex_source(piece) for is_math, piece in pieces if not is_math
    ):
        return False
    widths = [
        math_em(part)
        for is_math, piece in math_spans(_quote_markup(text))
        if is_math
        for part in _math_parts(quote_math(piece))
    ]
    return max(widths) > _QUOTE_BELOW_EM


def _below_words(text: str) -> str:
    """The Printed cell of a claim whose quote is shown under its row (:func:`quote_below`)."""
    text = _DISPLAY.sub(lambda m: "$" + m.group(1) + "$", text)
    words = "".join(piece for is_math, piece in math_spans(text) if not is_math).strip(" .,;:")
    return "the quote below" if words else "the equation below"


def _reproduced_text(e: Evaluation) -> str:
    if _is_truth(e.reproduced):
        return _statement_word(bool(e.reproduced), printed=False)
    return _plain_with_unit(format_value(e.reproduced), e.claim.unit)


def _value_html(text: str) -> str:
    r"""A value with its unit (:func:`_plain_with_unit`) as HTML: the number and a plain unit
    kept on one line (:func:`_nowrap`), a unit set as math typeset.

    Examples
    --------
    >>> print(_value_html("3.986×10¹⁴ $\\mathrm{m}^{3}$"))
    3.986×10¹⁴&nbsp;<span class="math notranslate nohighlight">\(\mathrm{m}^{3}\)</span>
    """
    return "".join(
        html_text(f"${piece}$") if is_math else _nowrap(piece) for is_math, piece in math_spans(text)
    )


def _nowrap(text: str) -> str:
    """A short value kept on one line (number and unit together); words ("does not hold")
    and long text may wrap at their spaces."""
    escaped = html.escape(text)
    short_number = len(text) <= 16 and any(ch.isdigit() for ch in text)
    return escaped.replace(" ", "&nbsp;") if short_number else escaped


def _tolerance_text(e: Evaluation) -> str:
    """The tolerance and its reason in one phrase; empty for an exact truth value (a
    statement either holds or not)."""
    tol = e.tolerance if e.tolerance is not None else e.claim.tolerance
    if not hasattr(tol, "describe"):
        return ""
    size, reason = tol.describe(), getattr(tol, "reason", "")
    if size == "exact" and e.claim.is_statement:
        return ""
    if reason.lower().startswith(size.lower()):
        return reason
    return f"{size}: {reason}" if reason else size


def _reading_label(name: str, value: Any) -> str | None:
    """The words of a convention's reading whose value is the code word ``value`` (``"C/N0"``:
    "$C/N_0$ in dB-Hz"), as the conventions table shows it; ``None`` for anything else."""
    if not isinstance(value, str):
        return None
    try:
        inp = get_input(name)
    except (KeyError, ValueError):
        return None
    return next((label for label, v in inp.readings if v == value), None)


#: Longest text of a table-valued input in a claim's inputs; longer ones end after a row.
_TABLE_TEXT_WIDTH = 100


def _table_value_text(value: Any) -> str | None:
    r"""A table-valued input (rows of cells, or a mapping) as a reader reads it, never as Python
    prints a list: a numeric matrix by its size ("a $3 \times 6$ matrix"), other rows as
    their cells ("Position 3, Velocity 3, ..."), cut after a row and counted when long;
    ``None`` for a value that is not a table.

    Examples
    --------
    >>> _table_value_text([["Position", 3], ["Velocity", 3]])
    'Position 3, Velocity 3'
    >>> _table_value_text([[1, 0, -1], [0, 1, 0]])
    'a $2 \\times 3$ matrix'
    >>> _table_value_text([["a long row name " * 3, i] for i in range(5)])[-8:]
    '(5 rows)'
    >>> _table_value_text([1, 2]) is None
    True
    """
    if isinstance(value, dict):
        rows: list[Any] = [[k, v] for k, v in value.items()]
    elif isinstance(value, list | tuple) and value and all(isinstance(r, list | tuple) for r in value):
        rows = list(value)
    else:
        return None
    numeric = all(isinstance(c, int | float) and not isinstance(c, bool) for r in rows for c in r)
    widths = {len(r) for r in rows}
    if numeric and len(widths) == 1:
        return f"a ${len(rows)} \\times {widths.pop()}$ matrix"

    def cell(c: Any) -> str:
        return format_value(c) if isinstance(c, int | float) else str(c)

    texts = [" ".join(cell(c) for c in r) for r in rows]
    whole = ", ".join(texts)
    if len(whole) <= _TABLE_TEXT_WIDTH:
        return whole
    kept: list[str] = []
    for t in texts:
        if len(", ".join([*kept, t])) > _TABLE_TEXT_WIDTH - 12:
            break
        kept.append(t)
    return ", ".join(kept) + f", … ({len(rows)} rows)"


def _inputs_text(e: Evaluation) -> str:
    """The inputs the computation read: name, value (a convention's code word as its reading's
    words), where it comes from."""
    parts = []
    for i in e.inputs:
        value = i.get("value")
        label, unit = _label_and_unit(i["name"])
        reading = _reading_label(i["name"], value)
        if reading is not None:  # words written for a reader: whole, never cut inside a formula
            shown = reading
        elif isinstance(value, list | tuple) and all(
            isinstance(v, int | float) and not isinstance(v, bool) for v in value
        ):  # a reading that sets several numbers: each as a number, not as Python prints a list
            shown = "(" + ", ".join(format_value(v) for v in value) + ")"
        elif (table := _table_value_text(value)) is not None:
            shown = table
            reading = table  # already short: not cut below
        else:
            shown = format_value(value) if isinstance(value, int | float) else str(value)
        if reading is None and len(shown) > 40:
            shown = shown[:39] + "…"
        elif isinstance(value, int | float) and not isinstance(value, bool):
            shown = _plain_with_unit(shown, unit)
        where = i.get("provenance", "")
        if i.get("locator"):
            where += f", {i['locator']}"
        parts.append(f"{label} = {shown} ({where})")
    return "; ".join(parts)


def _band_text(e: Evaluation) -> str:
    """The details' band line: its ends at the digits of the note's sentences (one precision per
    claim, :func:`~navcore.ledger.core.note_digits`); ``""`` when they print the same."""
    if e.band is None or e.claim.is_statement:
        return ""
    lo, hi = e.band
    digits = e._note_digits()
    low, high = format_value(lo, digits), format_value(hi, digits)
    if low == high:  # a range whose two ends print the same: no range
        return ""
    left_out = left_out_of_band(e)
    return (
        f"{low} to {high}"
        + (f" {unit_text(e.claim.unit)}" if e.claim.unit not in ("", "statement") else "")
        + (f" (left out, outside the model's domain: {left_out})" if left_out else "")
    )


def _agreeing_reading_text(e: Evaluation) -> str:
    """Where only readings other than the one used agree, or the one used agrees only over a
    band too wide to decide while another decides: "agrees under: <labels>".

    Each agreeing reading the note shows (:meth:`~navcore.ledger.core.Evaluation.shown_readings`:
    not those that differ only in conventions whose readings change nothing) is named by what
    it changes from the one used (the labels of the reading used are not repeated); a reading
    that only adds changes to another agreeing reading listed is left out."""
    nominal = next((r for r in e.readings if r["nominal"]), None)
    if nominal is None:
        return ""
    # the readings the note shows: those of conventions that change nothing are folded away
    shown = e.shown_readings()
    if nominal["agrees"]:
        if not nominal.get("band_too_wide") or e.status != "consistent":
            return ""
        agreeing = [r for r in shown if r["agrees"] and not r.get("band_too_wide")]
    else:
        agreeing = [r for r in shown if r["agrees"]]
    inert = set(e.inert_conventions())
    changes = []
    for r in agreeing:
        changed = tuple(
            (name, label)
            for name, label in r["reading"].items()
            if name not in inert and label != nominal["reading"].get(name, PRECISION_STRICT)
        )
        if changed and changed not in changes:
            changes.append(changed)
    # a reading whose changes include another listed reading's adds nothing to "agrees under"
    minimal = [c for c in changes if not any(set(o) < set(c) for o in changes)]
    labels = ["; ".join(reader_label(label) for _, label in c) for c in minimal]
    return "agrees under: " + " / ".join(labels) if labels else ""


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
    :func:`claim_group` of their locators (``"Table 2.6"``).

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

    Claims are grouped by what they check (:func:`claim_group` of their locators):
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
                    what += " (" + _tex_escape(where) + ")"
                if self.show_notes:
                    own = _details_tex(g.own(index))
                    what += r"\newline{}{\scriptsize \texttt{" + _tex_breakable(c.id) + "}"
                    what += (". " + own if own else "") + "}"
                colour = _status_colour(e.status).lstrip("#").upper()
                verdict = rf"\cellcolor[HTML]{{{colour}}}" + _tex_breakable(e.status)
                if not e.passes:
                    verdict += r" \textbf{(check fails)}"
                if c.erratum:
                    verdict += r"\newline{}{\scriptsize " + _tex_breakable(c.erratum) + "}"
                if _agreeing_reading_text(e):
                    verdict += r"\newline{}{\scriptsize " + tex_text(_agreeing_reading_text(e)) + "}"
                verdict += r"\newline{}{\scriptsize\itshape " + _tex_escape(str(c.kind)) + "}"
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


_SOFT_HYPHENS = {
    "typography": "typo&shy;graphy",
    "convention": "con&shy;vention",
    "derivation": "deri&shy;vation",
    "assumption": "as&shy;sumption",
    "overstatement": "over&shy;statement",
    "reproduced": "repro&shy;duced",
    "consistent": "consis&shy;tent",
    "inconsistent": "incon&shy;sistent",
    "discrepant": "discrep&shy;ant",
    "reproducible": "repro&shy;ducible",
    # the papers' locator words
    "Appendix": "Ap&shy;pen&shy;dix",
    "discussion": "dis&shy;cus&shy;sion",
    "approximation": "ap&shy;prox&shy;i&shy;ma&shy;tion",
    "acceleration": "ac&shy;cel&shy;er&shy;a&shy;tion",
    "sensitivity": "sen&shy;si&shy;tiv&shy;i&shy;ty",
    "covariance": "co&shy;vari&shy;ance",
    "corollary": "cor&shy;ol&shy;lary",
    "assertion": "as&shy;ser&shy;tion",
    "acquisition": "ac&shy;qui&shy;si&shy;tion",
    "inertial": "in&shy;er&shy;tial",
    "residual": "resid&shy;ual",
    "equation": "equa&shy;tion",
    "comment": "com&shy;ment",
    "Theorem": "The&shy;o&shy;rem",
    "caption": "cap&shy;tion",
    "paragraph": "para&shy;graph",
    "conclusion": "con&shy;clu&shy;sion",
    "Introduction": "In&shy;tro&shy;duc&shy;tion",
    "abstract": "ab&shy;stract",
    "Abstract": "Ab&shy;stract",
    "definition": "def&shy;i&shy;ni&shy;tion",
    "footnote": "foot&shy;note",
}


def _breakable_heading(text: str) -> str:
    """A column heading that may break in a narrow window: between words, after a hyphen,
    and at a soft hyphen inside the verdict names."""
    words = []
    for word in text.split(" "):
        parts = [_SOFT_HYPHENS.get(part, html.escape(part)) for part in word.split("-")]
        words.append("-<wbr>".join(parts))
    return "<br>".join(words)


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
    (:data:`~navcore.ledger.core.TEXT_ONLY_CAVEAT`) is said once, under the heading of the
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
                out.append(r"\noindent{}" + _tex_escape(TEXT_ONLY_CAVEAT) + r"\par")
            for e in items:
                claims_tex = (
                    "; ".join(
                        r"\texttt{"
                        + _tex_breakable(c)
                        + "}"
                        + (f" ({_tex_escape(self.status[c])})" if c in self.status else "")
                        for c in e.claims
                    )
                    or "none"
                )
                out += [
                    r"\par\medskip\noindent\textbf{"
                    + _tex_breakable(e.id)
                    + "} ("
                    + _tex_escape(e.paper)
                    + ", "
                    + tex_text(e.locator)
                    + r")\nopagebreak",
                    r"\begin{itemize}",
                    r"\item \textit{Basis:} "
                    + _tex_escape(e.basis)
                    + r"; \textit{kind:} "
                    + _tex_escape(e.kind),
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

    The text-only caveat (:data:`~navcore.ledger.core.TEXT_ONLY_CAVEAT`) follows the counts
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
        from navcore.ledger.summary import finding_evidence, findings_count_table

        self.items = list(items)
        self.root = root
        self.list_findings = list_findings
        self.rows = findings_count_table(self.items)
        self.evidence = finding_evidence(self.items, list(evals))

    def _table(self) -> tuple[list[str], list[list[str]]]:
        from navcore.ledger.core import ERRATUM_KINDS

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


_LEDGER_JS = r"""
(function () {
  function ready(fn) {
    if (document.readyState !== "loading") fn(); else document.addEventListener("DOMContentLoaded", fn);
  }
  function csvCell(v) {
    if (v === null || v === undefined) return "";
    if (typeof v === "object") v = JSON.stringify(v);
    v = String(v);
    return /[",\n]/.test(v) ? '"' + v.replace(/"/g, '""') + '"' : v;
  }
  function flatten(rec) {
    var out = {};
    Object.keys(rec).forEach(function (k) {
      var v = rec[k];
      if (v && typeof v === "object" && !Array.isArray(v)) {
        Object.keys(v).forEach(function (j) { out[k + "." + j] = v[j]; });
      } else out[k] = v;
    });
    return out;
  }
  // what built the page (commit, lock hash, versions), which the book puts beside the ledger
  function provenance() {
    var el = document.getElementById("navcore-provenance");
    return el ? JSON.parse(el.textContent) : null;
  }
  function buildColumns(prov) {  // as BuildProvenance.flat(): build_commit, ..., build_numpy
    var out = {};
    if (!prov) return out;
    Object.keys(prov).forEach(function (k) {
      if (k !== "packages") out["build_" + k] = prov[k];
    });
    Object.keys(prov.packages || {}).forEach(function (name) {
      out["build_" + name.replace(/-/g, "_")] = prov.packages[name];
    });
    return out;
  }
  function download(name, type, text) {
    var a = document.createElement("a");
    a.href = URL.createObjectURL(new Blob([text], {type: type}));
    a.download = name;
    document.body.appendChild(a);
    a.click();
    setTimeout(function () { URL.revokeObjectURL(a.href); a.remove(); }, 0);
  }
  ready(function () {
    document.querySelectorAll("[data-ledger-app]").forEach(function (app) {
      if (app.dataset.ready) return;
      app.dataset.ready = "1";
      var data = JSON.parse(app.querySelector("script.ledger-data").textContent);
      var tbody = app.querySelector("tbody");
      var rows = Array.prototype.slice.call(tbody.querySelectorAll("tr[data-index]"));
      var search = app.querySelector("input[type=search]");
      var selects = app.querySelectorAll("select[data-filter]");
      var count = app.querySelector(".ledger-count");
      var sortKey = null, sortDir = 1;
      function visible() {
        var q = (search.value || "").toLowerCase().trim();
        var want = {};
        selects.forEach(function (s) { if (s.value) want[s.dataset.filter] = s.value; });
        return rows.filter(function (tr) {
          var rec = data[+tr.dataset.index];
          for (var k in want) if (String(rec[k]) !== want[k]) return false;
          // the soft hyphens of long locator words (U+00AD) are not part of the text searched
          return !q || tr.textContent.replace(/\u00ad/g, "").toLowerCase().indexOf(q) >= 0;
        });
      }
      function update() {
        var keep = visible();
        rows.forEach(function (tr) { tr.hidden = true; });
        keep.forEach(function (tr) { tr.hidden = false; });
        count.textContent = keep.length + " of " + rows.length + " claims";
      }
      function rank(v) {
        return typeof v === "number" ? 0 : v === null || v === undefined || v === "" ? 2 : 1;
      }
      function value(tr, key) {
        var v = data[+tr.dataset.index][key];
        if (v && typeof v === "object") v = JSON.stringify(v);
        return v;
      }
      var sortSelect = app.querySelector("select[data-sort]");
      var sortButton = app.querySelector("button[data-sort-dir]");
      // sort by a column (the headings on a wide screen, the sort menu on the cards);
      // no key restores the ledger's order
      function sortBy(key, dir) {
        sortKey = key;
        sortDir = dir;
        app.querySelectorAll("th[data-key]").forEach(function (o) {
          if (key && o.dataset.key === key) o.setAttribute("aria-sort", dir > 0 ? "ascending" : "descending");
          else o.removeAttribute("aria-sort");
        });
        if (sortSelect) sortSelect.value = key || "";
        if (sortButton) sortButton.textContent = dir > 0 ? "ascending" : "descending";
        rows.sort(function (a, b) {
          if (!key) return +a.dataset.index - +b.dataset.index;
          var x = value(a, key), y = value(b, key);
          var rx = rank(x), ry = rank(y);
          if (rx !== ry) return rx - ry;  // numbers, then text and true/false, then blanks
          if (rx === 0) return dir * (x - y);
          if (rx === 2) return 0;
          return dir * String(x).localeCompare(String(y), undefined, {numeric: true});
        });
        rows.forEach(function (tr) { tbody.appendChild(tr); });
      }
      app.querySelectorAll("th[data-key]").forEach(function (th) {
        th.querySelector("button").addEventListener("click", function () {
          var key = th.dataset.key;
          sortBy(key, sortKey === key ? -sortDir : 1);
        });
      });
      if (sortSelect) {
        sortSelect.addEventListener("change", function () { sortBy(sortSelect.value || null, 1); });
      }
      if (sortButton) sortButton.addEventListener("click", function () { sortBy(sortKey, -sortDir); });
      search.addEventListener("input", update);
      selects.forEach(function (s) { s.addEventListener("change", update); });
      app.querySelectorAll("button[data-download]").forEach(function (b) {
        b.addEventListener("click", function () {
          var recs = visible().map(function (tr) { return data[+tr.dataset.index]; });
          var prov = provenance();
          if (b.dataset.download === "json") {
            var doc = {provenance: prov, claims: recs};
            download("ledger.json", "application/json", JSON.stringify(doc, null, 2) + "\n");
          } else {
            var build = buildColumns(prov);
            var flat = recs.map(function (r) { return Object.assign(flatten(r), build); }), keys = [];
            flat.forEach(function (r) {
              Object.keys(r).forEach(function (k) { if (keys.indexOf(k) < 0) keys.push(k); });
            });
            var lines = [keys.map(csvCell).join(",")].concat(flat.map(function (r) {
              return keys.map(function (k) { return csvCell(r[k]); }).join(",");
            }));
            download("ledger.csv", "text/csv", lines.join("\n") + "\n");
          }
        });
      });
      app.classList.add("ledger-app-ready");
      update();
    });
  });
})();
"""


def _band_html(record: dict[str, Any], unit: str) -> str:
    """The interactive table's band cell: each end kept whole with its unit; a statement's band
    in words (whether it holds across the assumed ranges: throughout, for some inputs, or not).

    Examples
    --------
    >>> _band_html({"band": [0.5, 2.0]}, "m")
    '0.5 –&nbsp;2&nbsp;m'
    >>> _band_html({"band": [False, True]}, "statement")
    'holds for some inputs'
    """
    band = record.get("band")
    if not band:
        return ""
    low, high = band
    if isinstance(low, bool) or isinstance(high, bool):
        if low == high:
            return "holds throughout" if low else "fails throughout"
        return "holds for some inputs"
    if format_value(low) == format_value(high):  # both ends print the same: no range to show
        return ""
    ends = (
        format_value(low),
        format_value(high) + (f" {unit_text(unit)}" if unit not in ("", "statement") else ""),
    )
    return f"{_nowrap(ends[0])} –&nbsp;{_value_html(ends[1])}"


def _left_out_brief(e: Evaluation) -> str:
    """A band cell's note of the runs left out: "1 run left out" (the claim's note says which
    case, and that it lies outside the model's domain)."""
    return f"{_n_runs(sum(c['runs'] for c in e.left_out))} left out"


class InteractiveLedger:
    """The whole ledger as one table that sorts, filters, searches and downloads, offline.

    HTML: a plain table (readable without JavaScript) with a small inline script that sorts
    by any column, filters by paper, verdict and (when the claims carry it) kind, searches the
    text, and downloads the rows shown as CSV or JSON (the records of
    :meth:`~navcore.ledger.core.Evaluation.as_json`, so the download is the command line's
    JSON; see :func:`json_export` and :func:`csv_export`), with the build's provenance where
    the book put it on the page (a JSON script element ``navcore-provenance``). Columns for
    the optional record fields ``kind`` and ``band`` appear when any claim has them. The
    columns share the text column's width (the stylesheet's shares add up to 100 %); below
    900 px each row becomes a card without its empty fields, sorted by a menu instead of the
    column headings. PDF: a compact table without notes.

    Parameters
    ----------
    evals : sequence of Evaluation
        The claims to show, in order.
    root : str, optional
        Link prefix from the showing page to the book's root.

    Examples
    --------
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> table = InteractiveLedger([ev])
    >>> [r["status"] for r in table.records], "data-ledger-app" in table._repr_html_()
    (['reproduced'], True)
    """

    def __init__(self, evals: Sequence[Evaluation], *, root: str = "") -> None:
        self.evals = list(evals)
        self.root = root
        self.records = [e.as_json() for e in self.evals]

    def _columns(self) -> list[tuple[str, str]]:
        cols = [("id", "Claim"), ("paper", "Paper")]
        if any(r.get("kind") for r in self.records):
            cols.append(("kind", "Kind"))
        cols += [("locator", "Locator"), ("quantity", "Quantity"), ("published", "Printed")]
        cols.append(("reproduced", "Reproduced"))
        if any(r.get("band") for r in self.records):
            cols.append(("band", "Band"))
        cols.append(("status", "Verdict"))
        return cols

    def _select(self, key: str, label: str, values: list[str]) -> str:
        options = "".join(f'<option value="{html.escape(v)}">{html.escape(v)}</option>' for v in values)
        return (
            f'<label>{html.escape(label)} <select data-filter="{key}">'
            f'<option value="">all</option>{options}</select></label>'
        )

    def _repr_html_(self) -> str:
        cols = self._columns()
        papers = list(dict.fromkeys(r["paper"] for r in self.records))
        order = {s: i for i, s in enumerate((*STATUSES, "inconsistent"))}
        statuses = sorted({r["status"] for r in self.records}, key=lambda s: (order.get(s, 99), s))
        controls = [
            '<input type="search" placeholder="Search claims" aria-label="Search claims">',
            self._select("paper", "Paper", papers),
            self._select("status", "Verdict", statuses),
        ]
        if any(r.get("kind") for r in self.records):
            kinds = sorted({r["kind"] for r in self.records if r.get("kind")})
            controls.append(self._select("kind", "Kind", kinds))
        sort_options = "".join(f'<option value="{k}">{html.escape(h)}</option>' for k, h in cols)
        controls.append(
            '<span class="ledger-sort"><label>Sort by <select data-sort>'
            f'<option value="">the ledger\'s order</option>{sort_options}</select></label>'
            '<button type="button" data-sort-dir title="reverse the order">ascending</button></span>'
        )
        controls += [
            '<span class="ledger-count" aria-live="polite"></span>',
            '<span class="ledger-downloads">Download the rows shown: '
            '<button type="button" data-download="csv">CSV</button> '
            '<button type="button" data-download="json">JSON</button></span>',
        ]
        head = "".join(
            f'<th data-key="{k}" scope="col"><button type="button" title="sort">{html.escape(h)}'
            "</button></th>"
            for k, h in cols
        )
        body = []
        for index, (e, rec, r) in enumerate(zip(self.evals, self.records, rows(self.evals), strict=True)):
            status = html.escape(r["status"]) + ("" if r["check"] == "ok" else " <b>(check fails)</b>")
            if r["erratum"]:
                anchor = html.escape(r["erratum"].lower())
                status += f'<br><a href="{self.root}errata.html#{anchor}">{html.escape(r["erratum"])}</a>'
            if _agreeing_reading_text(e):
                status += f'<br><span class="ledger-reading">{html_text(_agreeing_reading_text(e))}</span>'
            claim = f"<code>{html.escape(r['id'])}</code>"
            if r["discussed_in"]:
                target = html.escape(f"{self.root}{r['discussed_in']}.html#{r['id'].lower()}")
                claim = f'<a href="{target}" title="where the book derives it">{claim}</a>'
            note = (
                html_text(r["note"])
                + f"<br><i>Tolerance:</i> {html.escape(r['tolerance'])}, {html_text(r['tolerance_reason'])}"
            )
            cells = {
                "id": claim,
                "paper": html.escape(str(rec.get("paper", ""))),
                "kind": html.escape(str(rec.get("kind") or "")),
                "locator": soft_hyphens(html.escape(r["locator"])),
                # a long formula wraps in the narrow column, in a box of its own
                "quantity": html_text(r["quantity"], wide=_FIT_MATH_CHARS)
                + f"<details><summary>note</summary>{note}</details>",
                "published": _printed_html(_printed_text(e), fold=40),
                "reproduced": _value_html(_reproduced_text(e)),
                "band": _band_html(rec, r["unit"])
                + (
                    f'<br><span class="ledger-reading">{html.escape(_left_out_brief(e))}</span>'
                    if e.left_out and rec.get("band")
                    else ""
                ),
                "status": status,
            }
            tds = "".join(
                f'<td class="ledger-col-{k}{"" if cells[k] else " ledger-empty"}" '
                f'data-label="{html.escape(h)}">{cells[k]}</td>'
                for k, h in cols
            )
            body.append(
                f'<tr id="{html.escape(r["id"].lower())}" data-index="{index}" '
                f'class="{_status_class(r["status"])}">{tds}</tr>'
            )
        data = json.dumps(self.records, ensure_ascii=False, sort_keys=True).replace("</", "<\\/")
        return (
            '<div class="ledger-app" data-ledger-app>'
            f'<div class="ledger-controls">{"".join(controls)}</div>'
            f'<script type="application/json" class="ledger-data">{data}</script>'
            '<div class="ledger-table-wrap"><table class="ledger-table ledger-interactive">'
            f"<thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table></div>"
            f"<script>{_LEDGER_JS}</script></div>"
        )

    def _repr_markdown_(self) -> str:
        return "```{raw} latex\n" + LedgerTable(self.evals, show_notes=False).latex() + "\n```"

    def __repr__(self) -> str:
        return text_table(self.evals)
