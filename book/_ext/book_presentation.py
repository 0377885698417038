"""What readers see of the notebooks: erratum boxes from the ledger, the papers' numbering.

Errata. ``{erratum} <id>`` shows an erratum's warning box, built from its ``Erratum`` object
(what the paper prints, what the book finds, the evidence); each erratum discussed on a page
gets an anchor, which the errata page links to.

A page's build helpers (``glue(...)``, ``book.show_figure(...)``, ``book.setup()``,
``%matplotlib``) stand in cells the page itself hides: what a reader sees is what the
downloaded notebook runs, and the book gate fails on a shown cell with a helper.

Numbering. One scheme for figures, theorems and exercises, in HTML and in the PDF:

- a figure named ``fig-<paper>-<n>[-<m>...]`` (or ``fig-<paper>-fig<n>``) reproduces the
  paper's figure and carries its number: ``fig-atc10-2-1`` is Fig. 2.1, and
  ``fig-atc10-3-3-to-3-6`` (one grid for a run of the paper's figures) is Fig. 3.3–3.6;
- a theorem titled ``Theorem <n> of <paper>...`` carries the paper's number ``<n>`` and
  keeps the rest of the title;
- everything the book adds is numbered N1, N2, ... per chapter (figures and theorems), so
  that it cannot be mistaken for one of the paper's; exercises restart at 1 in each chapter.

HTML takes these numbers from ``env.toc_fignumbers``, which this extension overwrites after
Sphinx has assigned its sequential ones; the LaTeX writer gets ``\\thefigure`` set before
each figure, and sphinx-proof and sphinx-exercise read ``env.toc_fignumbers`` in both.
"""

from __future__ import annotations

import re
import sys
from typing import Any

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.environment import BuildEnvironment
from sphinx.errors import ExtensionError
from sphinx.util.docutils import SphinxDirective

PAPERS = ("wf", "sp", "atc10", "kzl")
FIGURE_RE = re.compile(r"^fig-(?:wf|sp|atc10|kzl)-(?:fig)?(\d+(?:-\d+)*)$")
# one figure of the book that redraws a run of the paper's figures: fig-atc10-3-3-to-3-6
FIGURE_RANGE_RE = re.compile(r"^fig-(?:wf|sp|atc10|kzl)-(?:fig)?(\d+(?:-\d+)*)-to-(\d+(?:-\d+)*)$")
THEOREM_RE = re.compile(r"^Theorem\s+([A-Z]?\d+(?:\.\d+)*)\s+of\s+(.*)$")


def paper_figure_number(name: str) -> str | None:
    """The paper's figure number that a figure name carries, or None for the book's own.

    ``fig-atc10-2-1`` carries 2.1; ``fig-atc10-3-3-to-3-6`` (one grid redrawing four of the
    paper's figures) carries 3.3–3.6.
    """
    m = FIGURE_RANGE_RE.match(name)
    if m:
        return f"{m.group(1).replace('-', '.')}\u2013{m.group(2).replace('-', '.')}"
    m = FIGURE_RE.match(name)
    return m.group(1).replace("-", ".") if m else None


def _captions(app: Sphinx, doctree: nodes.document) -> None:
    """A reproduced figure's caption does not repeat its number ("Fig. 2.1: Fig. 2.1 redrawn")."""
    for figure in doctree.findall(nodes.figure):
        number = next((paper_figure_number(i) for i in figure.get("ids", []) if paper_figure_number(i)), None)
        caption = next(iter(figure.findall(nodes.caption)), None)
        if number is None or caption is None:
            continue
        first = next(iter(caption.findall(nodes.Text)), None)
        if first is None:
            continue
        text = first.astext()
        m = re.match(rf"^(?:Fig\.|Figure)\s*{re.escape(number)}\b[\s:.,]*", text)
        if m:
            rest = text[m.end() :]
            first.parent.replace(first, nodes.Text(rest[:1].upper() + rest[1:]))


# --- errata boxes ------------------------------------------------------------------------------


class ErratumDirective(SphinxDirective):
    """``{erratum} <id>``: the erratum's warning box, built from its ``Erratum`` object.

    The box says what the paper prints (and where), what the book finds and the evidence, in
    the erratum's own words (:func:`navcore.book.erratum_box`); it takes no content, so no
    page writes an erratum's text by hand. An unknown id, or a box on another page than the
    erratum's ``discussed_in``, stops the build. The page is read again when the paper module
    that declares the erratum changes.
    """

    required_arguments = 1
    has_content = False

    def run(self) -> list[nodes.Node]:
        from navcore import ledger
        from navcore.book import erratum_box

        erratum_id = self.arguments[0]
        try:
            title, paragraphs = erratum_box(erratum_id, self.env.docname)
        except ValueError as exc:
            raise ExtensionError(f"{self.get_location()}: {{erratum}} {erratum_id}: {exc}") from exc
        box = nodes.admonition(classes=["warning", "erratum-box"])
        box += nodes.title(title, title)
        for pieces in paragraphs:
            para = nodes.paragraph()
            for style, text in pieces:
                if style == "math":
                    para += nodes.math(text, text)
                elif style == "label":
                    para += nodes.strong(text, text)
                else:
                    para += nodes.Text(text)
            box += para
        self.set_source_info(box)
        for name in ledger.paper_modules():
            module = sys.modules.get(name)
            if module is not None and any(e.id == erratum_id for e in getattr(module, "ERRATA", ())):
                self.env.note_dependency(module.__file__)
        return [box]


# --- anchors for errata -------------------------------------------------------------------------

ERRATUM_RE = re.compile(r"\b(?:WF|SP|ATC10|KZL)-E[0-9.]*-[A-Za-z0-9.-]*[A-Za-z0-9]")


def _erratum_anchors(app: Sphinx, doctree: nodes.document) -> None:
    """Give each erratum discussed on a page an anchor (its id in lower case).

    The admonition titled ``Erratum <id>`` gets it; an erratum only named in the text gets it
    on the first paragraph that names it. The errata page links its "Discussed in" there.
    """
    done: set[str] = set()
    for node in doctree.findall(nodes.admonition):
        title = next(iter(node.findall(nodes.title)), None)
        m = ERRATUM_RE.search(title.astext()) if title is not None else None
        if m and title.astext().lstrip().startswith("Erratum") and m.group(0).lower() not in done:
            node["ids"].append(m.group(0).lower())
            done.add(m.group(0).lower())
    for para in doctree.findall(nodes.paragraph):
        for m in ERRATUM_RE.finditer(para.astext()):
            anchor = m.group(0).lower()
            if anchor not in done:
                para["ids"].append(anchor)
                done.add(anchor)


# --- numbering ---------------------------------------------------------------------------------


def _chapter(docname: str) -> str:
    return docname.split("/")[0] if "/" in docname else ""


def _collect_titles(app: Sphinx, doctree: nodes.document) -> None:
    """Theorems titled 'Theorem 3.1 of ATC-10': remember 3.1, keep 'ATC-10' as the title."""
    env = app.env
    found: dict[str, str] = {}
    for node in doctree.findall(nodes.Element):
        if node.get("countertype") != "theorem" and node.get("realtype") != "theorem":
            continue
        title = next(iter(node.findall(nodes.title)), None)
        if title is None or not node.get("ids"):
            continue
        text = title.astext()
        # sphinx-proof's title node reads "Theorem #<n> (Title)"; match the parenthesised part
        m = re.search(r"\((.*)\)\s*$", text, re.S)
        inner = m.group(1) if m else text
        tm = THEOREM_RE.match(inner.strip())
        if tm is None:
            continue
        found[node["ids"][0]] = tm.group(1)
        rest = re.sub(r"\s*\(([^()]*)\)$", r", \1", tm.group(2))  # no parentheses in parentheses
        for text_node in list(title.findall(nodes.Text)):
            if inner.strip() in text_node.astext():
                new = text_node.astext().replace(inner.strip(), rest)
                text_node.parent.replace(text_node, nodes.Text(new))
    if not hasattr(env, "paper_theorem_numbers"):
        env.paper_theorem_numbers = {}
    env.paper_theorem_numbers[env.docname] = found


def _purge(app: Sphinx, env: BuildEnvironment, docname: str) -> None:
    getattr(env, "paper_theorem_numbers", {}).pop(docname, None)


def _merge(app: Sphinx, env: BuildEnvironment, docnames: set[str], other: BuildEnvironment) -> None:
    if not hasattr(env, "paper_theorem_numbers"):
        env.paper_theorem_numbers = {}
    env.paper_theorem_numbers.update(getattr(other, "paper_theorem_numbers", {}))


def _renumber(app: Sphinx, env: BuildEnvironment) -> list[str]:
    """Overwrite Sphinx's sequential numbers: the paper's where reproduced, N<k> per chapter."""
    own: dict[tuple[str, str], int] = {}
    theorems = getattr(env, "paper_theorem_numbers", {})
    for docname, kinds in env.toc_fignumbers.items():
        chapter = _chapter(docname)
        for kind, numbers in kinds.items():
            if kind in ("displaymath", "code-block", "table"):
                continue  # equations: paper_equations; no numbered code or tables
            for node_id in list(numbers):
                if kind == "figure":
                    paper = paper_figure_number(node_id)
                elif kind == "theorem":
                    paper = theorems.get(docname, {}).get(node_id)
                else:
                    paper = None
                if paper is not None:
                    numbers[node_id] = (paper,)
                    continue
                if kind == "solution":
                    continue  # a solution refers to its exercise's number
                key = (chapter, kind)
                own[key] = own.get(key, 0) + 1
                numbers[node_id] = (str(own[key]) if kind == "exercise" else f"N{own[key]}",)
    return []


def _latex_figure_numbers(app: Sphinx, doctree: nodes.document, docname: str) -> None:
    """LaTeX numbers figures with its own counter: set ``\\thefigure`` before each figure."""
    if app.builder.format != "latex":
        return
    for figure in list(doctree.findall(nodes.figure)):
        ids = figure.get("ids") or []
        if not ids:
            continue
        number = None
        for doc in (docname, figure.get("docname")):
            number = number or app.env.toc_fignumbers.get(doc or "", {}).get("figure", {}).get(ids[0])
        if number is None:
            for nums in app.env.toc_fignumbers.values():
                if ids[0] in nums.get("figure", {}):
                    number = nums["figure"][ids[0]]
                    break
        if number:
            tag = ".".join(map(str, number))
            raw = nodes.raw("", rf"\renewcommand{{\thefigure}}{{{tag}}}" + "\n", format="latex")
            figure.parent.insert(figure.parent.index(figure), raw)


def _print_hidden_inputs(app: Sphinx, doctree: nodes.document, docname: str) -> None:
    """In print, a cell whose source the web page folds away (``hide-input``) shows its result only.

    The HTML keeps such a source behind a "Show code cell source" toggle; paper has no toggle,
    so the LaTeX builder drops it instead of printing the bookkeeping in full.
    """
    if app.builder.format != "latex":
        return
    for cell in list(doctree.findall(nodes.container)):
        if "cell" in cell["classes"] and "tag_hide-input" in cell["classes"]:
            for child in list(cell.children):
                if isinstance(child, nodes.container) and "cell_input" in child["classes"]:
                    cell.remove(child)


def _print_proof_titles(app: Sphinx, doctree: nodes.document, docname: str) -> None:
    """In print, a proof box is titled "Proof" like the theorem box above it.

    sphinx-proof's proof is an admonition without a title whose text starts "Proof. "; the
    LaTeX builder prints it as a box with an empty title bar. The word moves into the title.
    """
    if app.builder.format != "latex":
        return
    for box in list(doctree.findall(nodes.admonition)):
        if "proof" not in box["classes"] or any(isinstance(c, nodes.title) for c in box.children):
            continue
        kind = next((c for c in box["classes"] if c != "proof"), "proof").title()
        first = next(iter(box.findall(nodes.Text)), None)
        prefix = f"{kind}. "
        if first is not None and str(first).startswith(prefix):
            first.parent.replace(first, nodes.Text(str(first)[len(prefix) :]))
        box.insert(0, nodes.title("", kind))


def _words_links_in_text_font(app: Sphinx, doctree: nodes.document, docname: str) -> None:
    """A link to the API reference whose text is words reads in the body font.

    Sphinx sets the text of a ``{py:func}`` / ``{py:class}`` cross-reference as code, which is
    right for a name (``federated_fuse``) but makes a phrase in running prose ("the federated
    fusion") look like code, on the web and in print. A link text with a space is a phrase:
    it keeps its link and loses the code font.
    """
    for literal in list(doctree.findall(nodes.literal)):
        if "xref" in literal["classes"] and " " in literal.astext().strip():
            words = nodes.inline("", literal.astext(), classes=["api-link"])
            literal.replace_self(words)


def setup(app: Sphinx) -> dict[str, Any]:
    # MathJax on every page: the ledger and errata pages hold math only in generated HTML
    # (claim notes and errata written with $...$), which Sphinx does not count as equations
    app.set_html_assets_policy("always")
    app.add_directive("erratum", ErratumDirective)
    app.connect("doctree-read", _erratum_anchors)
    app.connect("doctree-read", _captions)
    app.connect("doctree-read", _collect_titles)
    app.connect("env-purge-doc", _purge)
    app.connect("env-merge-info", _merge)
    # after the toctree collector (priority 500) has assigned Sphinx's own numbers
    app.connect("env-get-updated", _renumber, priority=900)
    app.connect("doctree-resolved", _latex_figure_numbers)
    app.connect("doctree-resolved", _print_hidden_inputs)
    app.connect("doctree-resolved", _print_proof_titles)
    app.connect("doctree-resolved", _words_links_in_text_font)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
