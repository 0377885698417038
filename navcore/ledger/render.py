"""Rendering the ledger: plain text for the terminal, HTML and Markdown for the book.

The book shows tables through :class:`LedgerTable`, an object with both ``_repr_html_``
(coloured by status, for the HTML builder) and ``_repr_markdown_`` (a plain pipe table that
MyST turns into a real LaTeX table for the PDF builder).
"""

from __future__ import annotations

import html
import json
import math
from collections.abc import Iterable, Sequence
from typing import Any

from navcore.ledger.core import STATUSES, Erratum, Evaluation
from navcore.ledger.registry import counts, errata, evaluations

__all__ = [
    "STATUS_COLOURS",
    "CountsTable",
    "ErrataList",
    "LedgerTable",
    "format_value",
    "json_dump",
    "rows",
    "text_table",
]

STATUS_COLOURS = {
    "reproduced": "#d8f0d8",
    "consistent": "#e6f0fa",
    "inconsistent": "#f6e7f7",
    "discrepant": "#fbe3d4",
    "not-reproducible": "#eeeeee",
    "error": "#ffb3b3",
}


def format_value(value: Any, digits: int = 5) -> str:
    """Format a published or reproduced value for a table."""
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "true" if value else "false"
    v = float(value)
    if math.isinf(v):
        return "∞" if v > 0 else "−∞"
    if v == int(v) and abs(v) < 1e6:
        return str(int(v))
    return f"{v:.{digits}g}"


def _published(e: Evaluation) -> str:
    c = e.claim
    rel = "" if c.relation == "=" else c.relation.replace(">=", "≥").replace("<=", "≤") + " "
    return rel + format_value(c.published)


def rows(evals: Iterable[Evaluation]) -> list[dict[str, str]]:
    """Table rows (strings) for a sequence of evaluations."""
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
                "expected_status": c.expected_status,
                "check": "ok" if e.passes else "FAIL",
                "note": e.note(),
                "tolerance_reason": getattr(tol, "reason", ""),
                "erratum": c.erratum,
                "discussed_in": c.discussed_in,
            }
        )
    return out


def text_table(evals: Sequence[Evaluation], *, width: int = 38) -> str:
    """A fixed-width text table with a counts footer (for ``python -m navcore ledger``)."""
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
    """The ledger as a JSON array of claim objects (LEDGER.md fields), stable and sorted."""
    return json.dumps([e.as_json() for e in evals], indent=2, ensure_ascii=False, sort_keys=False)


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
    """Escaped text that may break after ``-``, ``.`` and ``_`` (claim and erratum ids)."""
    out = _tex_escape(text)
    for ch in ("-", "."):
        out = out.replace(ch, ch + r"\allowbreak{}")
    return out.replace(r"\_", r"\_\allowbreak{}")


def _plain_with_unit(value: str, unit: str) -> str:
    if value in ("", "—") or unit in ("", "statement"):
        return value
    return f"{value} {unit}"


def _with_unit(value: str, unit: str) -> str:
    """A table cell: the value with its unit (statements and dimensionless values bare)."""
    if value in ("", "—") or unit in ("", "statement"):
        return html.escape(value)
    return f"{html.escape(value)}&nbsp;{html.escape(unit)}"


class LedgerTable:
    """Published-versus-reproduced table for the book (HTML coloured, Markdown for PDF).

    Parameters
    ----------
    evals : sequence of Evaluation
        The claims to show, in order.
    show_notes : bool
        Include the note and tolerance reason (HTML: as a second line; Markdown: a column).
    link_errata : bool
        Link erratum ids to their entry on the errata page.
    root : str
        Relative path from the page showing the table to the book's root (``"../"`` for a
        chapter page, ``""`` for a top-level page).
    link_pages : bool
        Link each claim id to its row on the page that discusses it (for the ledger page).
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

    def _repr_html_(self) -> str:
        head = ["Claim", "Locator", "Quantity", "Published", "Reproduced", "Status"]
        out = ['<div class="ledger-table-wrap"><table class="ledger-table">', "<thead><tr>"]
        out += [f"<th>{h}</th>" for h in head]
        out.append("</tr></thead><tbody>")
        for r in rows(self.evals):
            colour = STATUS_COLOURS[r["status"]]
            status = html.escape(r["status"])
            if r["check"] != "ok":
                status += " <b>(check fails)</b>"
            if r["erratum"] and self.link_errata:
                anchor = r["erratum"].lower()
                status += f'<br><a href="{self.root}errata.html#{anchor}">{html.escape(r["erratum"])}</a>'
            claim_id = f'<code id="{html.escape(r["id"].lower())}">{html.escape(r["id"])}</code>'
            if self.link_pages and r["discussed_in"]:
                target = f"{self.root}{r['discussed_in']}.html#{r['id'].lower()}"
                claim_id = f'<a href="{html.escape(target)}" title="where the book derives it">{claim_id}</a>'
            cells = [
                claim_id,
                html.escape(r["locator"]),
                html.escape(r["quantity"]),
                _with_unit(r["published"], r["unit"]),
                _with_unit(r["reproduced"], r["unit"]),
                status,
            ]
            out.append(
                f'<tr style="background:{colour}">' + "".join(f"<td>{c}</td>" for c in cells) + "</tr>"
            )
            if self.show_notes:
                note = (
                    html.escape(r["note"])
                    + f"<br><i>Tolerance:</i> {html.escape(r['tolerance'])}, "
                    + html.escape(r["tolerance_reason"])
                )
                out.append(
                    f'<tr class="ledger-note" style="background:{colour}"><td></td>'
                    f'<td colspan="5"><small>{note}</small></td></tr>'
                )
        out.append("</tbody></table></div>")
        return "".join(out)

    def _repr_markdown_(self) -> str:
        """A raw-LaTeX block for the PDF book (MyST renders Markdown outputs there).

        A ``longtable`` whose paragraph columns add up to the text width, rows coloured by
        status as in HTML, each claim's note in a full-width row below it, and claim ids
        that may break after ``-`` and ``.``; the HTML builder uses :meth:`_repr_html_`.
        """
        return "```{raw} latex\n" + self.latex() + "\n```"

    def latex(self) -> str:
        """The table as a LaTeX ``longtable`` that fits the text width."""
        widths = (0.15, 0.13, 0.31, 0.12, 0.13, 0.16)
        cols = "".join(
            rf">{{\raggedright\arraybackslash}}p{{\dimexpr {w}\linewidth-2\tabcolsep\relax}}" for w in widths
        )
        head = " & ".join(
            rf"\textbf{{{h}}}" for h in ("Claim", "Locator", "Quantity", "Published", "Reproduced", "Status")
        )
        out = [
            r"\begingroup\footnotesize\setlength{\tabcolsep}{3pt}\sloppy",
            rf"\begin{{longtable}}{{{cols}}}",
            rf"\hline {head} \\ \hline \endfirsthead",
            rf"\hline {head} \\ \hline \endhead",
            r"\hline \endfoot",
        ]
        for r in rows(self.evals):
            colour = STATUS_COLOURS[r["status"]].lstrip("#").upper()
            status = _tex_escape(r["status"]) + ("" if r["check"] == "ok" else r" \textbf{(check fails)}")
            if r["erratum"]:
                status += r"\newline{}\scriptsize " + _tex_breakable(r["erratum"])
            cells = [
                r"\texttt{" + _tex_breakable(r["id"]) + "}",
                _tex_escape(r["locator"]),
                _tex_escape(r["quantity"]),
                _tex_escape(_plain_with_unit(r["published"], r["unit"])),
                _tex_escape(_plain_with_unit(r["reproduced"], r["unit"])),
                status,
            ]
            out.append(rf"\rowcolor[HTML]{{{colour}}}" + " & ".join(cells) + r" \\*")
            if self.show_notes:
                note = (
                    _tex_escape(r["note"])
                    + r" \textit{Tolerance:} "
                    + _tex_escape(f"{r['tolerance']}, {r['tolerance_reason']}")
                )
                out.append(
                    rf"\rowcolor[HTML]{{{colour}}}\multicolumn{{6}}{{p{{\dimexpr\linewidth-2\tabcolsep\relax}}}}"
                    rf"{{\scriptsize {note}}} \\ \hline"
                )
            else:
                out.append(r"\hline")
        out += [r"\end{longtable}", r"\endgroup"]
        return "\n".join(out)

    def __repr__(self) -> str:
        return text_table(self.evals)


class CountsTable:
    """Counts of claims per paper and status (HTML and Markdown)."""

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
        out = ['<table class="ledger-counts"><thead><tr>']
        out += [f"<th>{h}</th>" for h in head]
        out.append("</tr></thead><tbody>")
        for r in body:
            out.append("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>")
        out.append("</tbody></table>")
        return "".join(out)

    def _repr_markdown_(self) -> str:
        head, body = self._table()
        lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
        lines += ["| " + " | ".join(r) + " |" for r in body]
        return "\n".join(lines)


class ErrataList:
    """The errata as a list of entries (HTML with anchors; Markdown for the PDF)."""

    def __init__(self, items: Sequence[Erratum] | None = None, *, root: str = "") -> None:
        self.items = list(errata() if items is None else items)
        self.root = root

    def _repr_html_(self) -> str:
        out = []
        for e in self.items:
            page = html.escape(e.discussed_in)
            link = html.escape(f"{self.root}{e.discussed_in}.html")
            where = f' Discussed in <a href="{link}">{page}</a>.' if e.discussed_in else ""
            claims_html = ", ".join(f"<code>{html.escape(c)}</code>" for c in e.claims) or "none"
            out.append(
                f'<div class="erratum" id="{html.escape(e.id.lower())}">'
                f"<h4>{html.escape(e.id)} — {html.escape(e.paper)}, {html.escape(e.locator)}</h4>"
                f"<p><b>Printed:</b> {html.escape(e.printed)}</p>"
                f"<p><b>The book finds:</b> {html.escape(e.finding)}</p>"
                f"<p><b>Evidence:</b> {html.escape(e.evidence)}</p>"
                f"<p><b>Claims affected:</b> {claims_html}.{where}</p></div>"
            )
        return "".join(out) or "<p>No errata registered.</p>"

    def _repr_markdown_(self) -> str:
        out = []
        for e in self.items:
            claims_md = ", ".join(f"`{c}`" for c in e.claims) or "none"
            out.append(
                f"**{e.id}** ({e.paper}, {e.locator})\n\n"
                f"- *Printed:* {e.printed}\n- *The book finds:* {e.finding}\n"
                f"- *Evidence:* {e.evidence}\n- *Claims affected:* {claims_md}\n"
            )
        return "\n".join(out) or "No errata registered."
