"""Build provenance on the book's pages: the About page's table, the PDF's title page, the ledger's downloads.

What built the book (the commit and whether the tree was clean, the commit's date, the lock
file's hash, Python's and the core packages' versions) comes from
:func:`navcore.provenance.build_provenance`, computed once per Sphinx process when the book is
built, never while a notebook executes (an executed page comes from the execution cache, which
a new commit does not invalidate). Everything in it is taken from the commit, so two builds of
one commit give the same bytes.

* ``{build-provenance}``: a directive that writes the provenance as a two-column table (the
  About page).
* The PDF's title page: the commit's date instead of the build's, and the provenance in small
  type under it.
* A page with the interactive ledger gets the provenance as a JSON script element
  (``navcore-provenance``), which its JSON and CSV downloads carry.

The downloadable notebooks get theirs in ``book_downloads``.
"""

from __future__ import annotations

import json
from functools import cache
from typing import Any

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.util.docutils import SphinxDirective

from navcore.provenance import BuildProvenance, build_provenance

SCRIPT_ID = "navcore-provenance"


@cache
def provenance() -> BuildProvenance:
    """This build's provenance (one computation per process)."""
    return build_provenance()


def provenance_table(rows: list[tuple[str, str]]) -> nodes.table:
    """A two-column table (what, value): hashes and versions as literals, words as text."""
    table = nodes.table(classes=["navcore-provenance"])
    group = nodes.tgroup(cols=2)
    table += group
    group += nodes.colspec(colwidth=30)
    group += nodes.colspec(colwidth=70)
    head = nodes.thead()
    group += head
    header = nodes.row()
    for text in ("Built with", "Value"):
        header += nodes.entry("", nodes.paragraph(text=text))
    head += header
    body = nodes.tbody()
    group += body
    for what, value in rows:
        row = nodes.row()
        row += nodes.entry("", nodes.paragraph(text=what))
        shown = nodes.Text(value) if " " in value else nodes.literal(text=value)
        row += nodes.entry("", nodes.paragraph("", "", shown))
        body += row
    return table


class BuildProvenanceDirective(SphinxDirective):
    """``{build-provenance}``: the table of what built this book."""

    has_content = False

    def run(self) -> list[nodes.Node]:
        return [provenance_table(provenance().rows())]


def _latex_escape(text: str) -> str:
    specials = {"&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_", "{": r"\{", "}": r"\}"}
    return "".join(specials.get(c, c) for c in text)


def title_page_latex(p: BuildProvenance) -> str:
    r"""The provenance block under the title page's date (``\authoraddress``), in small type."""
    lines = [rf"{_latex_escape(what)} & \texttt{{{_latex_escape(value)}}}\\" for what, value in p.rows()]
    return (
        "\\authoraddress{\\scriptsize\\begin{tabular}{@{}r@{\\enspace}l@{}}\n"
        "\\multicolumn{2}{r}{\\itshape Built from}\\\\\n" + "\n".join(lines) + "\n\\end{tabular}}\n"
    )


def _title_page(app: Sphinx) -> None:
    """The LaTeX title page: the commit's date, and the provenance under it."""
    if app.builder.name != "latex":
        return
    p = provenance()
    context = app.builder.context  # type: ignore[attr-defined]
    context["date"] = p.date if p.date != "unknown" else "commit date unknown"
    context["preamble"] = context.get("preamble", "") + "\n" + title_page_latex(p)


def _ledger_page(app: Sphinx, pagename: str, templatename: str, context: dict, doctree: Any) -> None:
    """A page with the interactive ledger carries the provenance its downloads include."""
    if app.builder.format != "html" or "data-ledger-app" not in context.get("body", ""):
        return
    data = json.dumps(provenance().as_dict(), sort_keys=True).replace("</", "<\\/")
    script = f'<script type="application/json" id="{SCRIPT_ID}">{data}</script>\n'
    context["metatags"] = context.get("metatags", "") + script


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_directive("build-provenance", BuildProvenanceDirective)
    app.connect("builder-inited", _title_page)
    app.connect("html-page-context", _ledger_page)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
