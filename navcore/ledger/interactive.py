"""The whole ledger as one interactive table (:class:`InteractiveLedger`): filters, columns
and a download of what is shown, run by a small script shipped with the package
(``ledger.js``, read with ``importlib.resources``).
"""

from __future__ import annotations

import html
import json
from collections.abc import Sequence
from importlib import resources
from typing import Any

from navcore.claims.declarations import STATUSES
from navcore.claims.evaluation import Evaluation, _n_runs
from navcore.formatting import unit_text
from navcore.ledger.tables import (
    LedgerTable,
    rows,
    text_table,
)
from navcore.ledger.text import (
    _FIT_MATH_CHARS,
    _agreeing_reading_text,
    _nowrap,
    _printed_html,
    _printed_text,
    _reproduced_text,
    _status_class,
    _value_html,
    format_value,
    html_text,
    soft_hyphens,
)

__all__ = ["InteractiveLedger"]


#: The interactive table's script, inlined in its ``<script>`` element (the file ships with the
#: package: an installed navcore reads it as package data).
_LEDGER_JS = "\n" + resources.files("navcore.ledger").joinpath("ledger.js").read_text(encoding="utf-8")


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
    :meth:`~navcore.claims.evaluation.Evaluation.as_json`, so the download is the command line's
    JSON; see :func:`~navcore.ledger.tables.json_export` and
    :func:`~navcore.ledger.tables.csv_export`), with the build's provenance where the book put it
    on the page (a JSON script element ``navcore-provenance``). Columns for
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
